#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <limits>

namespace ppp {

/// Seeded pseudo-random generator (xoshiro256**), identical on every platform.
/// Every random choice in PPP Lab draws from one of these; nothing is global or time-seeded.
class Rng {
 public:
  /// Standard-library name of the result type.
  using result_type = std::uint64_t;

  /// A generator whose whole state is derived from `seed` by SplitMix64.
  explicit Rng(std::uint64_t seed);

  /// The next 64 random bits.
  std::uint64_t next();
  /// Same as next(); makes Rng a UniformRandomBitGenerator.
  std::uint64_t operator()() { return next(); }
  /// Smallest value next() returns.
  static constexpr std::uint64_t min() { return 0; }
  /// Largest value next() returns.
  static constexpr std::uint64_t max() { return std::numeric_limits<std::uint64_t>::max(); }

  /// Uniform integer in [lo, hi] (inclusive), unbiased. Requires lo <= hi.
  std::int64_t uniformInt(std::int64_t lo, std::int64_t hi);
  /// Uniform integer in [0, n), unbiased. Requires n > 0.
  std::uint64_t below(std::uint64_t n);
  /// Uniform double in [0, 1) with 53 random bits.
  double uniform01();
  /// True with probability p (p <= 0 never, p >= 1 always).
  bool bernoulli(double p);

 private:
  std::uint64_t s_[4];
};

/// FNV-1a hash of a name, to derive seeds from names (not positions) with deriveSeed.
std::uint64_t nameHash(const std::string& name);

/// Derives an independent seed from a parent seed and a path of stream ids (set, PPP, agent, run...).
std::uint64_t deriveSeed(std::uint64_t parent, std::initializer_list<std::uint64_t> path);

}  // namespace ppp
