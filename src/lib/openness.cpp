#include "ppp_core/openness.hpp"

#include <algorithm>

namespace ppp {

namespace {

/// Mean longest free run over `lines` lines of `length` cells; cell i of line j is at first + j*line_step + i*step.
double meanLongestRun(const Grid& grid, int lines, int length, int line_step, int step) {
  const auto& cells = grid.cells();
  long total = 0;
  for (int line = 0; line < lines; ++line) {
    int run = 0;
    int longest = 0;
    for (int i = 0; i < length; ++i) {
      if (cells[static_cast<std::size_t>(line) * line_step + static_cast<std::size_t>(i) * step] == 0) {
        longest = std::max(longest, ++run);
      } else {
        run = 0;
      }
    }
    total += longest;
  }
  return static_cast<double>(total) / length / lines;
}

}  // namespace

double horizontalOpenness(const Grid& grid) {
  return meanLongestRun(grid, grid.height(), grid.width(), grid.width(), 1);
}

double verticalOpenness(const Grid& grid) { return meanLongestRun(grid, grid.width(), grid.height(), 1, grid.width()); }

}  // namespace ppp
