#include "ppp_agents/agent_memory.hpp"

#include <algorithm>
#include <cstring>

#include "ppp_agents/bit_masks.hpp"

namespace ppp {
namespace agents {

namespace {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "scan rows are read as little-endian words");

/// 0x80 in each byte of `bytes` equal to `value`, 0 in the others (no carries between bytes).
std::uint64_t bytesEqual(std::uint64_t bytes, std::int8_t value) {
  constexpr std::uint64_t kLow7 = 0x7F7F7F7F7F7F7F7FULL;
  const std::uint64_t differ = bytes ^ (0x0101010101010101ULL * static_cast<std::uint8_t>(value));
  return ~(((differ & kLow7) + kLow7) | differ | kLow7);
}

/// Bit i set where byte i of a bytesEqual() result is 0x80.
std::uint64_t gatherBytes(std::uint64_t high_bits) { return ((high_bits >> 7) * 0x0102040810204080ULL) >> 56; }

/// Scan cells `row[0 .. count)` (count <= 64) as two bit masks, bit i for cell i: seen free, seen obstacle.
/// Reads whole 8-byte words while they lie within the scan's kMaxScanCells bytes (`offset` is the row's
/// index in them), bytes past `count` masked off before use.
void rowMasks(const std::int8_t* row, int offset, int count, std::uint64_t* free, std::uint64_t* obstacle) {
  *free = 0;
  *obstacle = 0;
  int i = 0;
  for (; i < count && offset + i + 8 <= kMaxScanCells; i += 8) {
    std::uint64_t bytes;
    std::memcpy(&bytes, row + i, sizeof bytes);
    const std::uint64_t keep = count - i >= 8 ? ~std::uint64_t{0} : lowBits(8 * (count - i));
    *free |= gatherBytes(bytesEqual(bytes, kScanFree) & keep) << i;
    *obstacle |= gatherBytes(bytesEqual(bytes, kScanObstacle) & keep) << i;
  }
  for (; i < count; ++i) {
    *free |= static_cast<std::uint64_t>(row[i] == kScanFree) << i;
    *obstacle |= static_cast<std::uint64_t>(row[i] == kScanObstacle) << i;
  }
}

}  // namespace

void AgentMemory::reset(int width, int height, int window, int recent_scans) {
  width_ = width;
  height_ = height;
  window_ = window;
  recent_scans_ = recent_scans;
  scans_ = 0;
  if (recent_scans > 0) {
    seen_at_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), -1);
    recent_.assign(static_cast<std::size_t>(recent_scans), Written{0, 0, -1, -1});
  }
  words_per_row_ = (width + 63) / 64;
  last_position_ = Cell{-1, -1};
  const std::size_t words = static_cast<std::size_t>(words_per_row_) * static_cast<std::size_t>(height);
  free_.assign(words, 0);
  obstacle_.assign(words, 0);
}

void AgentMemory::forget(int y, int x0, int x1) {
  for (int x = x0; x <= x1; x += 64) {
    const int count = std::min(x1 - x + 1, 64);
    writeBits(y, x, count, lowBits(count), 0, 0);
  }
}

void AgentMemory::stamp(int y, int x0, std::uint64_t seen) {
  for (; seen != 0; seen &= seen - 1) {
    seen_at_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + x0 + __builtin_ctzll(seen)] = scans_;
  }
}

void AgentMemory::expire(const Written& written) {
  Written& oldest = recent_[static_cast<std::size_t>(scans_ % recent_scans_)];
  const long expired = scans_ - recent_scans_;
  for (int y = oldest.y0; y <= oldest.y1; ++y) {
    for (int x = oldest.x0; x <= oldest.x1; ++x) {
      if (seen_at_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + x] == expired) forget(y, x, x);
    }
  }
  oldest = written;
  ++scans_;
}

void AgentMemory::update(const Scan& scan) {
  const Cell p = scan.position();
  const int r = scan.range();
  const int side = 2 * r + 1;
  // With a limited window only cells within `keep` of the agent are written, so every remembered cell always
  // lies in the window around the last position and forgetting only has to look at the cells that left it.
  const int keep = window_ > 0 ? std::min(r, window_ / 2) : r;
  const int y0 = std::max(p.y - keep, 0);
  const int y1 = std::min(p.y + keep, height_ - 1);
  const int x0 = std::max(p.x - keep, 0);
  const int x1 = std::min(p.x + keep, width_ - 1);
  const int count = x1 - x0 + 1;
  WindowBits bits;
  const bool from_bits = scan.bits(&bits);  // the window as masks already: no cell to convert
  const std::int8_t* window = from_bits ? nullptr : scan.cells();
  for (int y = y0; y <= y1 && count > 0; ++y) {
    const int offset = (y - p.y + r) * side + (x0 - p.x + r);
    std::uint64_t seen_free;
    std::uint64_t seen_obstacle;
    if (from_bits) {
      seen_free = bits.free >> offset & lowBits(count);
      seen_obstacle = bits.obstacle >> offset & lowBits(count);
    } else {
      rowMasks(window + offset, offset, count, &seen_free, &seen_obstacle);
    }
    writeBits(y, x0, count, seen_free | seen_obstacle, seen_free, seen_obstacle);
    if (recent_scans_ > 0) stamp(y, x0, seen_free | seen_obstacle);
  }
  if (recent_scans_ > 0) expire(Written{x0, y0, x1, y1});
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
        if (y < new_y0 || y > new_y1) {
          forget(y, old_x0, old_x1);
          continue;
        }
        if (old_x0 <= std::min(old_x1, new_x0 - 1)) forget(y, old_x0, std::min(old_x1, new_x0 - 1));
        if (std::max(old_x0, new_x1 + 1) <= old_x1) forget(y, std::max(old_x0, new_x1 + 1), old_x1);
      }
    }
    last_position_ = p;
  }
}

}  // namespace agents
}  // namespace ppp
