#pragma once

#include <cstdint>

#include "ppp_core/sensor.hpp"

namespace ppp {

// A scan window of any sensor range as two bit masks, as windows travel in ppp_msgs/ScanBatch: bit i % 64 of word
// i / 64 stands for window cell i, row-major (cell 0 is the top-left of the window). A cell set in the free mask
// only was sensed free, in the obstacle mask only an obstacle, in both off the map; in neither it is unknown (not
// in line of sight).

/// Words of one window mask at the largest sensor range.
constexpr int kMaxWindowWords = (kMaxScanCells + 63) / 64;

/// Words of one window mask at sensor `range`: ceil((2 range + 1)^2 / 64).
inline int windowWords(int range) { return ((2 * range + 1) * (2 * range + 1) + 63) / 64; }

/// Writes the masks (windowWords(range) words each) of the (2 range + 1)^2 window `cells`.
void packWindow(const std::int8_t* cells, int range, std::uint64_t* free, std::uint64_t* obstacle);

/// Writes the (2 range + 1)^2 window cells of the masks.
void unpackWindow(const std::uint64_t* free, const std::uint64_t* obstacle, int range, std::int8_t* cells);

/// The one-word masks of a window of at most kMaxBitWindowCells cells.
inline void packWindow(const WindowBits& bits, std::uint64_t* free, std::uint64_t* obstacle) {
  *free = bits.free | bits.off_map;
  *obstacle = bits.obstacle | bits.off_map;
}

/// A window of at most kMaxBitWindowCells cells from its one-word masks.
inline WindowBits unpackWindow(std::uint64_t free, std::uint64_t obstacle) {
  return WindowBits{free & ~obstacle, obstacle & ~free, free & obstacle};
}

}  // namespace ppp
