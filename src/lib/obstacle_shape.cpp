#include "ppp_core/obstacle_shape.hpp"

#include <algorithm>
#include <vector>

namespace ppp {

namespace {

/// A rectangle of cells, row by row (true: obstacle).
struct Pattern {
  int width = 0;
  int height = 0;
  std::vector<bool> cells;
  bool at(int x, int y) const { return cells[static_cast<std::size_t>(y) * width + x]; }
};

/// `p` turned a quarter clockwise.
Pattern turned(const Pattern& p) {
  Pattern t{p.height, p.width, std::vector<bool>(p.cells.size())};
  for (int y = 0; y < t.height; ++y) {
    for (int x = 0; x < t.width; ++x) t.cells[static_cast<std::size_t>(y) * t.width + x] = p.at(y, p.height - 1 - x);
  }
  return t;
}

/// `p` mirrored left to right.
Pattern mirrored(const Pattern& p) {
  Pattern m{p.width, p.height, std::vector<bool>(p.cells.size())};
  for (int y = 0; y < m.height; ++y) {
    for (int x = 0; x < m.width; ++x) m.cells[static_cast<std::size_t>(y) * m.width + x] = p.at(p.width - 1 - x, y);
  }
  return m;
}

std::string text(const Pattern& p) {
  std::string out = std::to_string(p.width) + "x" + std::to_string(p.height) + ":";
  for (int y = 0; y < p.height; ++y) {
    if (y > 0) out += '/';
    for (int x = 0; x < p.width; ++x) out += p.at(x, y) ? '#' : '.';
  }
  return out;
}

}  // namespace

std::string obstacleShape(const Grid& grid) {
  int x0 = grid.width(), y0 = grid.height(), x1 = -1, y1 = -1;
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      if (!grid.isObstacle(Cell{x, y})) continue;
      x0 = std::min(x0, x);
      y0 = std::min(y0, y);
      x1 = std::max(x1, x);
      y1 = std::max(y1, y);
    }
  }
  if (x1 < 0) return "0x0:";
  Pattern pattern{x1 - x0 + 1, y1 - y0 + 1, {}};
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) pattern.cells.push_back(grid.isObstacle(Cell{x, y}));
  }
  std::string smallest = text(pattern);
  for (int flip = 0; flip < 2; ++flip) {
    Pattern p = flip == 0 ? pattern : mirrored(pattern);
    for (int turn = 0; turn < 4; ++turn, p = turned(p)) smallest = std::min(smallest, text(p));
  }
  return smallest;
}

}  // namespace ppp
