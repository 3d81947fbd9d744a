#pragma once

#include <functional>
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

/// What a search may do differently from optimisticAStar (the planted faults of planted_faults.hpp are made of
/// these): each left at its default, the search is optimisticAStar.
struct SearchRules {
  /// Whether a step from one cell may enter the next (default: GridMap::passable of the next). Cells off the map are
  /// never entered.
  std::function<bool(Cell from, Cell to)> can_step;
  long max_expansions = 0;      ///< Give up (no path) after expanding this many cells; 0: never.
  long max_open = 0;            ///< Give up (no path) when the open list holds more entries than this; 0: never.
};

/// A* under `rules`: optimisticAStar when every rule is left at its default.
std::vector<Cell> gridAStar(const GridMap& map, Cell start, Cell goal, const SearchRules& rules);

}  // namespace planners
}  // namespace ppp
