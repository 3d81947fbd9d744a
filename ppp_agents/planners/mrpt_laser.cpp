#include "mrpt_laser.hpp"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <limits>

namespace ppp {
namespace planners {

mrpt::maps::COccupancyGridMap2D mrptLaserMap(const Grid& grid, double resolution) {
  const double r = resolution;
  mrpt::maps::COccupancyGridMap2D map(-r, (grid.width() + 1) * r, -r, (grid.height() + 1) * r, r);
  const MapFrame frame{grid.width(), grid.height(), resolution};
  for (unsigned cy = 0; cy < map.getSizeY(); ++cy) {
    for (unsigned cx = 0; cx < map.getSizeX(); ++cx) {
      const int column = static_cast<int>(cx) - 1, row = static_cast<int>(cy) - 1;
      const bool inside = column >= 0 && row >= 0 && column < grid.width() && row < grid.height();
      const bool occupied = !inside || grid.isObstacle(frame.cellOfMapRowColumn(column, row));
      map.setCell(cx, cy, occupied ? 0.0f : 1.0f);
    }
  }
  return map;
}

void mrptScan(const mrpt::maps::COccupancyGridMap2D& map, const Pose2D& pose, const LaserBeams& beams,
              std::vector<float>* ranges) {
  mrpt::obs::CObservation2DRangeScan scan;
  const double aperture = beams.angle_increment * (beams.count - 1);
  scan.aperture = static_cast<float>(aperture);
  scan.maxRange = static_cast<float>(beams.range_max);
  scan.rightToLeft = true;
  // MRPT's beam i points at -aperture / 2 + i x increment from the pose's heading: turn the pose so that it points
  // at angle_min + i x increment from the robot's.
  const double turn = beams.angle_min + aperture / 2;
  map.laserScanSimulator(scan, mrpt::poses::CPose2D(pose.x, pose.y, pose.theta + turn), 0.5f, beams.count);
  ranges->resize(beams.count);
  for (int i = 0; i < beams.count; ++i) {
    (*ranges)[i] = scan.getScanRangeValidity(i) ? scan.getScanRange(i) : std::numeric_limits<float>::infinity();
  }
}

}  // namespace planners
}  // namespace ppp
