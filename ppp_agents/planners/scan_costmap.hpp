#pragma once

#include <cstdint>
#include <vector>

#include "ppp_core/map_frame.hpp"

namespace ppp {
namespace planners {

/// What the DWA example remembers of the world and its route, as move_base's costmap and global planner give them
/// to dwa_local_planner: a grid of small cells over the map's extent, marked where the robot's scans returned;
/// cells nearer a mark than the robot's radius are lethal, cells within the inflation radius cost more to cross
/// the nearer they are (so routes keep to the middle of passages), and a wavefront (8-connected, no corner
/// cutting, unknown cells free) gives every cell its cost to the goal: the route's length, weighted.
class ScanCostmap {
 public:
  /// The map's extent (`width` x `height` metres from `origin`, its bottom-left corner, in the map frame) in cells
  /// of `resolution` metres, for a robot of `radius` metres, obstacles inflated to `inflation_radius` metres.
  /// @throws InvalidArgument naming costmap_resolution or map when the grid would be empty or too large.
  ScanCostmap(double width, double height, MapPoint origin, double resolution, double radius, double inflation_radius);

  /// Marks the cell each of `returns` (a scan's returns seen from `from`, map frame) hit: the cell just across
  /// the face the return lies on (or just beyond it along its beam). A return on a cell's corner is skipped;
  /// returns off the map are ignored.
  void mark(MapPoint from, const std::vector<MapPoint>& returns);
  /// Spreads the wavefront from `goal` over what is marked now (unless nothing changed since the last plan).
  void plan(MapPoint goal);
  /// The cost of the route from `point` (map frame) to the goal of the last plan(): the least over the cells
  /// around `point` of their wavefront cost plus the straight line to them; +infinity where no route is known.
  double distance(MapPoint point) const;

 private:
  int cellAt(MapPoint point) const;  ///< -1 off the map
  MapPoint centre(int cell) const;

  int width_, height_;
  double resolution_;
  MapPoint origin_;
  double radius_, inflation_radius_;
  std::vector<std::uint8_t> marked_;
  std::vector<double> clearance_;  // metres from each cell's centre to the nearest marked cell's square
  std::vector<double> cost_;       // the wavefront
  std::vector<std::uint8_t> lethal_;  // plan()'s view of each cell: nearer a mark than the robot's radius
  std::vector<double> weight_;        // plan()'s cost factor of crossing each cell
  MapPoint goal_;
  bool changed_ = false, planned_ = false;
};

}  // namespace planners
}  // namespace ppp
