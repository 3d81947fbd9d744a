#pragma once

#include <array>

#include "ppp_agents/agent_memory.hpp"
#include "ppp_core/grid.hpp"

namespace ppp {
namespace agents {

/// For each 4-neighbour of `position` in kMoves order (North, East, South, West), how many cells a sensor of
/// range `range` (1..kMaxSensorRange) would reveal from there: cells on the map, unknown in `memory` and not
/// hidden behind a remembered obstacle (hidden: a remembered obstacle among the cells cellsCrossed() lists
/// between the neighbour and the cell), written to `gains`. Only neighbours with `evaluate[i]` are counted;
/// the others get 0.
///
/// Works on bit boards: the (2 * range + 3)^2 cells around `position` (every neighbour's window) become two
/// masks, unknown and obstacle; per neighbour, the obstacles in its window OR together their precomputed
/// shadows (the window cells each one hides), and the gain is the population count of the unknown window
/// cells outside them: a few dozen word operations instead of a line-of-sight walk per unknown cell.
void revealGains(const AgentMemory& memory, Cell position, int range, const std::array<bool, 4>& evaluate,
                 std::array<int, 4>* gains);

}  // namespace agents
}  // namespace ppp
