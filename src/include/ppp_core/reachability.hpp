#pragma once

#include <vector>

#include "ppp_core/connectivity.hpp"
#include "ppp_core/grid.hpp"

namespace ppp {

/// True when `goal` can be reached from `start` by 4-connected moves through free cells.
bool isReachable(const Grid& grid, Cell start, Cell goal);

/// Fewest moves from `from` to every cell (-1 where unreachable or an obstacle): 4-connected, or with the diagonal
/// moves octileMoveAllowed() allows under Connectivity::Eight.
std::vector<int> stepDistances(const Grid& grid, Cell from, Connectivity connectivity = Connectivity::Four);

/// Fewest moves from `start` to `goal` under the move model (-1 when the goal cannot be reached).
int fewestMoves(const Grid& grid, Cell start, Cell goal, Connectivity connectivity);

}  // namespace ppp
