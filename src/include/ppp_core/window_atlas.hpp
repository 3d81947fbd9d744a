#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ppp_core/grid.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {

/// Largest atlas worth keeping for one map (at range 2 a 20x20 map takes 20 KB, 200x200 2 MB); larger maps
/// or ranges are scanned step by step.
constexpr std::size_t kMaxWindowAtlasBytes = std::size_t{2} << 20;

/// The noiseless scan window of every cell of one grid, computed once: each step's scan becomes a copy
/// (plus noise) instead of a line-of-sight test per window cell.
class WindowAtlas {
 public:
  /// Bytes an atlas of `grid` at sensor `range` takes.
  static std::size_t bytes(const Grid& grid, int range) {
    const std::size_t cells = static_cast<std::size_t>(2 * range + 1) * (2 * range + 1);
    return static_cast<std::size_t>(grid.size()) * (cells + (cells <= kMaxBitWindowCells ? sizeof(WindowBits) : 0));
  }
  /// The windows of every cell of `grid` at sensor `range`. @throws InvalidArgument for a bad range.
  WindowAtlas(const Grid& grid, int range);
  /// Cells in one window, (2 * range + 1)^2.
  int cells() const { return cells_; }
  /// SensorModel::see(grid, position) for a cell of the grid.
  const std::int8_t* window(Cell position) const {
    return windows_.data() + static_cast<std::size_t>(position.y * width_ + position.x) * cells_;
  }
  /// window(position) as bit masks, or nullptr for windows of more than kMaxBitWindowCells cells.
  const WindowBits* bits(Cell position) const {
    return bits_.empty() ? nullptr : &bits_[static_cast<std::size_t>(position.y * width_ + position.x)];
  }

 private:
  int cells_;
  int width_;
  std::vector<std::int8_t> windows_;  // cells_ values per grid cell, in the grid's cell order
  std::vector<WindowBits> bits_;      // the same as masks, per grid cell (small windows only)
};

}  // namespace ppp
