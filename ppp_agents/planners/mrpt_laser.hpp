#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <vector>

#include "ppp_core/grid.hpp"
#include "ppp_core/kinematics.hpp"
#include "ppp_core/laser.hpp"

namespace ppp {
namespace planners {

/// MRPT's occupancy grid of `grid` at `resolution` metres per cell in the map frame, with a ring of occupied cells
/// around it standing for the border wall: the map MRPT's laserScanSimulator() casts on.
mrpt::maps::COccupancyGridMap2D mrptLaserMap(const Grid& grid, double resolution);

/// The ranges MRPT's laserScanSimulator() reads on `map` for a robot at `pose` with the beams `beams` (same
/// angles as scanLaser(): MRPT spreads its beams over its aperture with both edges included, so a full circle is
/// given as an aperture of (count - 1) increments and the pose turned to match); no return reads +infinity.
void mrptScan(const mrpt::maps::COccupancyGridMap2D& map, const Pose2D& pose, const LaserBeams& beams,
              std::vector<float>* ranges);

}  // namespace planners
}  // namespace ppp
