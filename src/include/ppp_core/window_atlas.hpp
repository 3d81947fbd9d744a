#pragma once

#include <cstdint>
#include <vector>

#include "ppp_core/grid.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {

/// The noiseless scan window of every cell of one grid, computed once: a simulator that sends every window
/// copies it instead of testing line of sight cell by cell each step (a 20x20 map at range 2 takes 10 KB).
class WindowAtlas {
 public:
  /// The windows of every cell of `grid` at sensor `range`. @throws InvalidArgument for a bad range.
  WindowAtlas(const Grid& grid, int range);
  /// Window radius.
  int range() const { return range_; }
  /// Cells in one window, (2 * range + 1)^2.
  int cells() const { return cells_; }
  /// SensorModel::see(grid, position) for a cell of the grid.
  const std::int8_t* window(Cell position) const {
    return windows_.data() + static_cast<std::size_t>(position.y * width_ + position.x) * cells_;
  }

 private:
  int range_;
  int cells_;
  int width_;
  std::vector<std::int8_t> windows_;  // cells_ values per grid cell, in the grid's cell order
};

}  // namespace ppp
