#pragma once

#include <vector>

#include "ppp_core/grid.hpp"

namespace ppp {

/// True when `goal` can be reached from `start` by 4-connected moves through free cells.
bool isReachable(const Grid& grid, Cell start, Cell goal);

/// Fewest 4-connected moves from `from` to every cell (-1 where unreachable or an obstacle).
std::vector<int> stepDistances(const Grid& grid, Cell from);

}  // namespace ppp
