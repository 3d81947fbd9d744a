#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "ppp_core/grid.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {
namespace agents {

/// The occupancy grid an agent builds from its scans: each cell unknown, free or obstacle (kScan* values).
/// With a window k > 0 only the k x k cells centred on the agent are kept; cells leaving it are forgotten.
class AgentMemory {
 public:
  /// Forgets everything; `window` 0 keeps the whole map.
  void reset(int width, int height, int window);
  /// Writes the scan's known cells (free, obstacle) into memory, then forgets what is outside the window.
  void update(const Scan& scan);
  /// The remembered value of a cell (kScanOutOfBounds off the map).
  std::int8_t at(Cell c) const {
    if (c.x < 0 || c.y < 0 || c.x >= width_ || c.y >= height_) return kScanOutOfBounds;
    return cells_[c.y * width_ + c.x];
  }
  /// True when the cell is on the map and remembered free.
  bool isFree(Cell c) const { return at(c) == kScanFree; }
  /// True when the cell is on the map and not remembered (neither free nor obstacle).
  bool isUnknown(Cell c) const { return at(c) == kScanUnknown; }
  /// Asks the processor to fetch the remembered cells within `reach` of `c` (none for a cell off the map).
  void prefetch(Cell c, int reach) const {
    if (c.x < 0 || c.y < 0 || c.x >= width_ || c.y >= height_) return;
    for (int y = std::max(c.y - reach, 0); y <= std::min(c.y + reach, height_ - 1); ++y) {
      __builtin_prefetch(cells_.data() + y * width_ + std::max(c.x - reach, 0));
    }
  }
  /// Map columns.
  int width() const { return width_; }
  /// Map rows.
  int height() const { return height_; }

 private:
  int width_ = 0;
  int height_ = 0;
  int window_ = 0;
  Cell last_position_{-1, -1};
  std::vector<std::int8_t> cells_;
};

}  // namespace agents
}  // namespace ppp
