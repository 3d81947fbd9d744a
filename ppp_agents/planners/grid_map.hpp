#pragma once

#include <cstdint>
#include <vector>

#include "ppp_core/grid.hpp"
#include "ppp_core/map_frame.hpp"

namespace ppp {
namespace planners {

/// Occupancy value of an unknown cell in nav_msgs/OccupancyGrid data.
constexpr std::int8_t kUnknownOccupancy = -1;
/// Occupancy from which a cell counts as an obstacle (the bridge marks obstacles 100, free cells 0).
constexpr std::int8_t kObstacleOccupancy = 50;

/// Which cells of a nav_msgs/OccupancyGrid a planner may use, in grid cells (y down) through ppp::MapFrame.
/// A cell is passable when it is on the map and free, or unknown and the map was built with unknown_is_free, and,
/// with an inflation, a disc of that radius centred in it covers no known obstacle and stays on the map.
class GridMap {
 public:
  /// Reads occupancy data laid out as in nav_msgs/OccupancyGrid (row-major, row 0 at the bottom).
  /// @throws InvalidArgument for sides outside the grid limits, a resolution that is not positive and finite,
  /// data of the wrong length, or a value outside -1 and [0, 100]. `inflation` is the robot's radius in map
  /// cells as the planner believes it (ppp/footprint.hpp; <= 0.5: none).
  GridMap(int width, int height, double resolution, const std::vector<std::int8_t>& data, bool unknown_is_free,
          double inflation = 0);

  /// Size and resolution, and the flip between grid cells and the map frame.
  const MapFrame& frame() const { return frame_; }
  /// True when the cell lies on the map.
  bool contains(Cell c) const { return c.x >= 0 && c.y >= 0 && c.x < frame_.width && c.y < frame_.height; }
  /// True when the cell is on the map and a planner may enter it.
  bool passable(Cell c) const { return contains(c) && passable_[index(c)] != 0; }
  /// The cell holding a map-frame point: the first cell ppp::walkMapSegment gives for it (may be off the map).
  /// @throws InvalidArgument for a coordinate that is not finite or absurdly far from the map.
  Cell cellOf(MapPoint p) const;
  /// The map-frame centre of a cell.
  MapPoint centre(Cell c) const { return MapPoint{frame_.centreX(c), frame_.centreY(c)}; }
  /// True when the straight segment can be walked either way: every cell ppp::walkMapSegment gives from a to b
  /// and from b to a (they differ only where the segment passes exactly through a cell corner) is passable.
  /// @throws InvalidArgument for a coordinate that is not finite or absurdly far from the map.
  bool segmentPassable(MapPoint a, MapPoint b) const;
  /// True when the path (map-frame waypoints joined by straight segments) passes through `cell`, walked as
  /// ppp::walkMapSegment walks each segment. A path of fewer than two waypoints passes nowhere.
  /// @throws InvalidArgument for a coordinate that is not finite or absurdly far from the map.
  bool pathPasses(const std::vector<MapPoint>& path, Cell cell) const;

 private:
  int index(Cell c) const { return c.y * frame_.width + c.x; }
  bool walkPassable(MapPoint from, MapPoint to) const;

  MapFrame frame_;
  std::vector<std::uint8_t> passable_;  // row-major, y down
};

}  // namespace planners
}  // namespace ppp
