#pragma once

#include <vector>

#include "ppp_core/grid.hpp"

namespace ppp {

/// Cost of a diagonal move in the 8-connected (octile) move model: sqrt(2).
constexpr double kDiagonalCost = 1.41421356237309504880;

/// True when a move from `from` by (dx, dy) (each -1, 0 or 1, not both 0) is allowed on `grid` under MovingAI's
/// 8-connected rule: the target is free and, for a diagonal, both orthogonal neighbours it passes are free (no
/// cutting a corner).
bool octileMoveAllowed(const Grid& grid, Cell from, int dx, int dy);

/// The octile distance between two cells on an empty map: max - min + sqrt(2) * min of |dx|, |dy|.
double octileDistance(Cell a, Cell b);

/// A shortest 8-connected route.
struct OctileRoute {
  double length = -1;      ///< 1 per straight move, sqrt(2) per diagonal; -1 when the goal cannot be reached.
  std::vector<Cell> cells;  ///< The route from start to goal, both included (empty when unreachable).
};

/// A shortest route from `start` to `goal` over free cells with octileMoveAllowed moves (A* with the octile
/// distance, exact: the length equals Dijkstra's). Both cells must be on the grid.
/// @throws InvalidArgument("start" or "goal", ...) for a cell off the grid.
OctileRoute shortestOctileRoute(const Grid& grid, Cell start, Cell goal);

}  // namespace ppp
