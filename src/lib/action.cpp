#include "ppp_core/action.hpp"

namespace ppp {

const char* actionName(Action action) {
  switch (action) {
    case Action::Stay: return "stay";
    case Action::North: return "north";
    case Action::East: return "east";
    case Action::South: return "south";
    case Action::West: return "west";
    case Action::NorthEast: return "north_east";
    case Action::SouthEast: return "south_east";
    case Action::SouthWest: return "south_west";
    case Action::NorthWest: return "north_west";
  }
  return "unknown";
}

}  // namespace ppp
