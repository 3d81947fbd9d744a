#pragma once

#include <vector>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include "grid_map.hpp"
#include "ppp_core/grid.hpp"

namespace ppp {
namespace planners {

/// MRPT's occupancy grid of a GridMap: the same extent and resolution (MRPT's y axis points up, as the map
/// frame's), cells free (probability of being free 1) where the GridMap is passable, occupied (0) elsewhere.
/// @throws Error when MRPT makes a grid of another size.
mrpt::maps::COccupancyGridMap2D mrptGridOf(const GridMap& map);

/// MRPT's wavefront planner for circular robots (mrpt::nav::PlannerSimple2D) on a GridMap: passable cells are
/// free for MRPT, every other cell an obstacle; MRPT grows the obstacles by `robot_radius` (its own way: ceil(R)
/// rounds of 8-neighbour growth) and searches 8-connected. Its behaviour is the library's, not ours, and a hunt
/// can find where it differs from the robot's world: it never expands through the map's outermost ring of cells
/// (only the start and goal may lie there), and it moves diagonally between two obstacles that touch at a
/// corner, which the 4-connected robot cannot.
class MrptGridPlanner {
 public:
  /// `robot_radius` in map cells (MRPT's robotRadius divided by the map's resolution; 0: obstacles not grown).
  /// @throws InvalidArgument naming robot_radius when it is negative or not finite.
  explicit MrptGridPlanner(double robot_radius);

  /// Waypoints from the start cell's centre through MRPT's path to the goal cell's centre; empty when MRPT finds
  /// no path. @throws Error with MRPT's message when MRPT fails (one of its internal checks).
  std::vector<MapPoint> plan(const GridMap& map, Cell start, Cell goal) const;

 private:
  double robot_radius_;
};

}  // namespace planners
}  // namespace ppp
