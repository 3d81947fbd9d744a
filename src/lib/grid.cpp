#include "ppp_core/grid.hpp"

#include <algorithm>
#include <string>

#include "ppp_core/error.hpp"

namespace ppp {

std::string cellText(Cell c) { return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")"; }

void validateGridSize(int width, int height, const char* what) {
  if (width < kMinGridSide || height < kMinGridSide || width > kMaxGridSide || height > kMaxGridSide) {
    throw InvalidArgument(what, "expected width and height in [" + std::to_string(kMinGridSide) + ", " +
                                    std::to_string(kMaxGridSide) + "], got " + std::to_string(width) + "x" +
                                    std::to_string(height));
  }
}

Grid::Grid(int width, int height) {
  validateGridSize(width, height);
  width_ = width;
  height_ = height;
  cells_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
}

std::uint64_t Grid::hash() const {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (std::uint8_t cell : cells_) h = (h ^ cell) * 0x100000001b3ULL;
  return h;
}

int Grid::obstacleCount() const { return static_cast<int>(std::count(cells_.begin(), cells_.end(), 1)); }

}  // namespace ppp
