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
/// With a limit of n recent scans only what the last n scans saw is kept: a cell none of them saw is forgotten.
/// Stored as two bit planes (free, obstacle; a cell in neither is unknown), rows of whole 64-bit words, so
/// that a scan is merged and a neighbourhood read a row of bits at a time.
class AgentMemory {
 public:
  /// Forgets everything; `window` 0 keeps the whole map, `recent_scans` 0 every scan's sightings.
  void reset(int width, int height, int window, int recent_scans = 0);
  /// Writes the scan's known cells (free, obstacle) into memory, then forgets what is outside the window.
  void update(const Scan& scan);
  /// The remembered value of a cell (kScanOutOfBounds off the map).
  std::int8_t at(Cell c) const {
    if (!onMap(c)) return kScanOutOfBounds;
    const std::size_t word = wordOf(c);
    const std::uint64_t bit = std::uint64_t{1} << (c.x & 63);
    return (obstacle_[word] & bit) != 0 ? kScanObstacle : (free_[word] & bit) != 0 ? kScanFree : kScanUnknown;
  }
  /// True when the cell is on the map and remembered free.
  bool isFree(Cell c) const { return onMap(c) && (free_[wordOf(c)] >> (c.x & 63) & 1) != 0; }
  /// True when the cell is on the map and not remembered (neither free nor obstacle).
  bool isUnknown(Cell c) const {
    return onMap(c) && ((free_[wordOf(c)] | obstacle_[wordOf(c)]) >> (c.x & 63) & 1) == 0;
  }
  /// The 64 cells of row `y` from column `x` (both on the map) as bits, bit i for cell x + i: remembered free.
  /// Columns past the row's end read 0.
  std::uint64_t freeBits(int y, int x) const { return bitsAt(free_, y, x); }
  /// As freeBits(), for remembered obstacles.
  std::uint64_t obstacleBits(int y, int x) const { return bitsAt(obstacle_, y, x); }
  /// Asks the processor to fetch the remembered rows within `reach` of `c` (none for a cell off the map).
  void prefetch(Cell c, int reach) const {
    if (!onMap(c)) return;
    const Cell left{std::max(c.x - reach, 0), 0};
    for (int y = std::max(c.y - reach, 0); y <= std::min(c.y + reach, height_ - 1); ++y) {
      __builtin_prefetch(free_.data() + wordOf(Cell{left.x, y}));
      __builtin_prefetch(obstacle_.data() + wordOf(Cell{left.x, y}));
    }
  }
  /// Map columns.
  int width() const { return width_; }
  /// Map rows.
  int height() const { return height_; }

 private:
  bool onMap(Cell c) const { return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_; }
  std::size_t wordOf(Cell c) const {
    return static_cast<std::size_t>(c.y) * words_per_row_ + static_cast<std::size_t>(c.x >> 6);
  }
  std::uint64_t bitsAt(const std::vector<std::uint64_t>& plane, int y, int x) const {
    const std::size_t word = wordOf(Cell{x, y});
    const int offset = x & 63;
    std::uint64_t bits = plane[word] >> offset;
    if (offset != 0 && (x >> 6) + 1 < words_per_row_) bits |= plane[word + 1] << (64 - offset);
    return bits;
  }
  /// Replaces `count` (at most 64) bits of row `y` from column `x` in both planes: cleared where `clear`
  /// has a bit, then `set_free` and `set_obstacle` ORed in.
  void writeBits(int y, int x, int count, std::uint64_t clear, std::uint64_t set_free, std::uint64_t set_obstacle) {
    const std::size_t word = wordOf(Cell{x, y});
    const int offset = x & 63;
    free_[word] = (free_[word] & ~(clear << offset)) | (set_free << offset);
    obstacle_[word] = (obstacle_[word] & ~(clear << offset)) | (set_obstacle << offset);
    if (offset + count > 64) {  // the rest spills into the next word
      const int shift = 64 - offset;
      free_[word + 1] = (free_[word + 1] & ~(clear >> shift)) | (set_free >> shift);
      obstacle_[word + 1] = (obstacle_[word + 1] & ~(clear >> shift)) | (set_obstacle >> shift);
    }
  }
  /// Forgets columns [x0, x1] of row `y`.
  void forget(int y, int x0, int x1);
  /// The cells a scan wrote: rows y0..y1, columns x0..x1.
  struct Written {
    int x0, y0, x1, y1;
  };
  /// With a limit of recent scans: stamps the cells of row `y` from `x0` that this scan saw (bits of `seen`).
  void stamp(int y, int x0, std::uint64_t seen);
  /// With a limit of recent scans: forgets what the scan that just fell out of the limit saw and no later one did,
  /// and keeps `written` in its place.
  void expire(const Written& written);

  int width_ = 0;
  int height_ = 0;
  int window_ = 0;
  int words_per_row_ = 0;
  Cell last_position_{-1, -1};
  int recent_scans_ = 0;             // 0: no limit of scans
  long scans_ = 0;                   // scans merged since reset
  std::vector<long> seen_at_;        // with a limit of scans: per cell, the scan that last saw it
  std::vector<Written> recent_;      // with a limit of scans: what each of the last recent_scans_ wrote
  std::vector<std::uint64_t> free_;      // bit x & 63 of word y * words_per_row_ + x / 64: remembered free
  std::vector<std::uint64_t> obstacle_;  // the same for remembered obstacles
};

}  // namespace agents
}  // namespace ppp
