#pragma once

#include <cstdint>

#include "ppp_core/grid.hpp"

namespace ppp {
namespace agents {

/// What an agent does in one step (the same numbers as ppp_msgs/MoveBatch). 4-connected moves;
/// North is towards row 0 (y down).
enum class Action : std::uint8_t { Stay = 0, North = 1, East = 2, South = 3, West = 4 };

/// Number of actions.
constexpr int kActionCount = 5;

/// The four moves in the order North, East, South, West.
constexpr Action kMoves[4] = {Action::North, Action::East, Action::South, Action::West};

/// The cell an action aims at (the same cell for Stay).
inline Cell target(Cell from, Action action) {
  switch (action) {
    case Action::North: return Cell{from.x, from.y - 1};
    case Action::East: return Cell{from.x + 1, from.y};
    case Action::South: return Cell{from.x, from.y + 1};
    case Action::West: return Cell{from.x - 1, from.y};
    case Action::Stay: break;
  }
  return from;
}

/// True for a number that names an action (for actions received from other processes).
inline bool isAction(int value) { return value >= 0 && value < kActionCount; }

/// The action's name ("stay", "north", ...).
const char* actionName(Action action);

}  // namespace agents
}  // namespace ppp
