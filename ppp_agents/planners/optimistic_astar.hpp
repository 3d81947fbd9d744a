#pragma once

#include <vector>

#include "grid_map.hpp"
#include "ppp_core/grid.hpp"

namespace ppp {
namespace planners {

/// A* on the 4-connected grid of a GridMap, Manhattan heuristic: every cell of a shortest path from `start`
/// to `goal`, both included, through passable cells (the start, where the robot stands, is not checked).
/// Empty when the goal is off the map, not passable or walled off. Ties are broken by a fixed order, so the
/// same map gives the same path. Built with unknown_is_free, the map makes this the optimistic unknown-terrain
/// planner: plan as if unknown cells were free, and plan again when the map shows otherwise.
std::vector<Cell> optimisticAStar(const GridMap& map, Cell start, Cell goal);

}  // namespace planners
}  // namespace ppp
