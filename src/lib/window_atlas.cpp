#include "ppp_core/window_atlas.hpp"

namespace ppp {

WindowAtlas::WindowAtlas(const Grid& grid, int range)
    : cells_((2 * range + 1) * (2 * range + 1)), width_(grid.width()) {
  const SensorModel sensor(SensorOptions{range, 0.0});
  windows_.resize(static_cast<std::size_t>(grid.size()) * cells_);
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) sensor.see(grid, Cell{x, y}, windows_.data() + (y * width_ + x) * cells_);
  }
  if (cells_ > kMaxBitWindowCells) return;
  bits_.resize(static_cast<std::size_t>(grid.size()));
  for (std::size_t c = 0; c < bits_.size(); ++c) {
    const std::int8_t* window = windows_.data() + c * static_cast<std::size_t>(cells_);
    for (int i = 0; i < cells_; ++i) {
      bits_[c].free |= static_cast<std::uint64_t>(window[i] == kScanFree) << i;
      bits_[c].obstacle |= static_cast<std::uint64_t>(window[i] == kScanObstacle) << i;
      bits_[c].off_map |= static_cast<std::uint64_t>(window[i] == kScanOutOfBounds) << i;
    }
  }
}

}  // namespace ppp
