#pragma once

#include <cstdint>

namespace ppp {
namespace agents {

/// The lowest `count` bits set (count 0..64).
inline std::uint64_t lowBits(int count) {
  return count >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << count) - 1;
}

/// Set bits of a word, inline (the builtin calls a library function on the baseline x86-64 target).
inline int bitCount(std::uint64_t x) {
  x -= (x >> 1) & 0x5555555555555555ULL;
  x = (x & 0x3333333333333333ULL) + ((x >> 2) & 0x3333333333333333ULL);
  x = (x + (x >> 4)) & 0x0F0F0F0F0F0F0F0FULL;
  return static_cast<int>((x * 0x0101010101010101ULL) >> 56);
}

}  // namespace agents
}  // namespace ppp
