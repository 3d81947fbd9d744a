#include "ppp_agents/agent_memory.hpp"

#include <algorithm>

namespace ppp {
namespace agents {

void AgentMemory::reset(int width, int height, int window) {
  width_ = width;
  height_ = height;
  window_ = window;
  last_position_ = Cell{-1, -1};
  cells_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), kScanUnknown);
}

void AgentMemory::update(const Scan& scan) {
  const Cell p = scan.position();
  const int r = scan.range();
  const int side = 2 * r + 1;
  const std::int8_t* window = scan.cells();
  // With a limited window only cells within `keep` of the agent are written, so every remembered cell always
  // lies in the window around the last position and forgetting only has to look at the cells that left it.
  const int keep = window_ > 0 ? std::min(r, window_ / 2) : r;
  const int y0 = std::max(p.y - keep, 0);
  const int y1 = std::min(p.y + keep, height_ - 1);
  const int x0 = std::max(p.x - keep, 0);
  const int x1 = std::min(p.x + keep, width_ - 1);
  for (int y = y0; y <= y1; ++y) {
    const std::int8_t* row = window + (y - p.y + r) * side + (x0 - p.x + r);
    std::int8_t* out = &cells_[static_cast<std::size_t>(y) * width_ + x0];
    for (int x = x0; x <= x1; ++x, ++row, ++out) {
      if (*row == kScanFree || *row == kScanObstacle) *out = *row;
    }
  }
  if (window_ > 0) {
    const Cell last = last_position_;
    if (last.x >= 0 && last != p) {
      // Forget the part of the old window that is not in the new one: for a one-cell move, one row or one
      // column of the old window, so O(k) per step.
      const int half = window_ / 2;
      const int new_y0 = p.y - half, new_y1 = p.y + half, new_x0 = p.x - half, new_x1 = p.x + half;
      const int old_y0 = std::max(last.y - half, 0), old_y1 = std::min(last.y + half, height_ - 1);
      const int old_x0 = std::max(last.x - half, 0), old_x1 = std::min(last.x + half, width_ - 1);
      for (int y = old_y0; y <= old_y1; ++y) {
        std::int8_t* row = &cells_[static_cast<std::size_t>(y) * width_];
        if (y < new_y0 || y > new_y1) {
          std::fill(row + old_x0, row + old_x1 + 1, kScanUnknown);
          continue;
        }
        for (int x = old_x0; x <= std::min(old_x1, new_x0 - 1); ++x) row[x] = kScanUnknown;
        for (int x = std::max(old_x0, new_x1 + 1); x <= old_x1; ++x) row[x] = kScanUnknown;
      }
    }
    last_position_ = p;
  }
}

}  // namespace agents
}  // namespace ppp
