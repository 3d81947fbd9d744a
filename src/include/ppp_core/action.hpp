#pragma once

#include <cstdint>

#include "ppp_core/connectivity.hpp"
#include "ppp_core/grid.hpp"

namespace ppp {

/// What an agent does in one step (the same numbers as ppp_msgs/MoveBatch). North is towards row 0 (y down).
/// The four diagonal moves exist only in the 8-connected move model (connectivity 8).
enum class Action : std::uint8_t {
  Stay = 0,
  North = 1,
  East = 2,
  South = 3,
  West = 4,
  NorthEast = 5,
  SouthEast = 6,
  SouthWest = 7,
  NorthWest = 8,
};

/// Number of actions of the 4-connected move model (stay and the four straight moves).
constexpr int kActionCount = 5;

/// Number of actions of the 8-connected move model (the above and the four diagonal moves).
constexpr int kOctileActionCount = 9;

/// The four moves in the order North, East, South, West.
constexpr Action kMoves[4] = {Action::North, Action::East, Action::South, Action::West};

/// The cell offset (dx, dy) of an action ((0, 0) for Stay).
inline Cell offset(Action action) {
  switch (action) {
    case Action::North: return Cell{0, -1};
    case Action::East: return Cell{1, 0};
    case Action::South: return Cell{0, 1};
    case Action::West: return Cell{-1, 0};
    case Action::NorthEast: return Cell{1, -1};
    case Action::SouthEast: return Cell{1, 1};
    case Action::SouthWest: return Cell{-1, 1};
    case Action::NorthWest: return Cell{-1, -1};
    case Action::Stay: break;
  }
  return Cell{0, 0};
}

/// The cell an action aims at (the same cell for Stay).
inline Cell target(Cell from, Action action) {
  const Cell d = offset(action);
  return Cell{from.x + d.x, from.y + d.y};
}

/// The move from `from` to its neighbour `to` (one of the 8 around it; Stay for `from` itself).
inline Action actionTowards(Cell from, Cell to) {
  static constexpr Action kByOffset[3][3] = {{Action::NorthWest, Action::North, Action::NorthEast},
                                             {Action::West, Action::Stay, Action::East},
                                             {Action::SouthWest, Action::South, Action::SouthEast}};
  const int dx = (to.x > from.x) - (to.x < from.x);
  const int dy = (to.y > from.y) - (to.y < from.y);
  return kByOffset[dy + 1][dx + 1];
}

/// True for the four diagonal moves.
inline bool isDiagonal(Action action) { return static_cast<int>(action) >= static_cast<int>(Action::NorthEast); }

/// True for a number that names an action of the move model `connectivity` (for actions received from other
/// processes).
inline bool isAction(int value, Connectivity connectivity = Connectivity::Four) {
  return value >= 0 && value < (connectivity == Connectivity::Eight ? kOctileActionCount : kActionCount);
}

/// The action's name ("stay", "north", ..., "north_west").
const char* actionName(Action action);

}  // namespace ppp
