#include "ppp_core/window_mask.hpp"

#include <algorithm>

namespace ppp {

void packWindow(const std::int8_t* cells, int range, std::uint64_t* free, std::uint64_t* obstacle) {
  const int words = windowWords(range);
  std::fill(free, free + words, 0);
  std::fill(obstacle, obstacle + words, 0);
  const int count = (2 * range + 1) * (2 * range + 1);
  for (int i = 0; i < count; ++i) {
    const std::uint64_t bit = std::uint64_t{1} << (i & 63);
    if (cells[i] == kScanFree || cells[i] == kScanOutOfBounds) free[i >> 6] |= bit;
    if (cells[i] == kScanObstacle || cells[i] == kScanOutOfBounds) obstacle[i >> 6] |= bit;
  }
}

void unpackWindow(const std::uint64_t* free, const std::uint64_t* obstacle, int range, std::int8_t* cells) {
  const int count = (2 * range + 1) * (2 * range + 1);
  for (int i = 0; i < count; ++i) {
    const bool is_free = (free[i >> 6] >> (i & 63) & 1) != 0;
    const bool is_obstacle = (obstacle[i >> 6] >> (i & 63) & 1) != 0;
    cells[i] = is_free && is_obstacle ? kScanOutOfBounds : is_free ? kScanFree : is_obstacle ? kScanObstacle : kScanUnknown;
  }
}

}  // namespace ppp
