#include "ppp_core/window_atlas.hpp"

namespace ppp {

WindowAtlas::WindowAtlas(const Grid& grid, int range)
    : cells_((2 * range + 1) * (2 * range + 1)), width_(grid.width()) {
  const SensorModel sensor(SensorOptions{range, 0.0});
  windows_.resize(static_cast<std::size_t>(grid.size()) * cells_);
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) sensor.see(grid, Cell{x, y}, windows_.data() + (y * width_ + x) * cells_);
  }
}

}  // namespace ppp
