#pragma once

#include <string>
#include <vector>

#include "ppp_core/grid.hpp"

namespace ppp {
namespace test {

/// A grid drawn as rows of '.' (free), '#' (obstacle), 'S' (start) and 'G' (goal).
struct Picture {
  Grid grid;
  Cell start;
  Cell goal;
};

/// Builds a grid from its drawing.
inline Picture picture(const std::vector<std::string>& rows) {
  Picture p{Grid(static_cast<int>(rows[0].size()), static_cast<int>(rows.size())), Cell{}, Cell{}};
  for (int y = 0; y < static_cast<int>(rows.size()); ++y) {
    for (int x = 0; x < static_cast<int>(rows[y].size()); ++x) {
      const char c = rows[y][x];
      if (c == '#') p.grid.setObstacle(Cell{x, y}, true);
      if (c == 'S') p.start = Cell{x, y};
      if (c == 'G') p.goal = Cell{x, y};
    }
  }
  return p;
}

}  // namespace test
}  // namespace ppp
