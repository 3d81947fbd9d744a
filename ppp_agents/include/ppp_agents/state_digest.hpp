#pragma once

#include <cstddef>
#include <cstdint>

namespace ppp {
namespace agents {

/// A 64-bit FNV-1a digest of an agent's decision state, built field by field: equal states give equal digests,
/// on every machine (no addresses, fixed byte order of the values added).
class StateDigest {
 public:
  /// Adds `count` bytes.
  void addBytes(const void* data, std::size_t count) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < count; ++i) mix(bytes[i]);
  }
  /// Adds a whole number, low byte first.
  void add(std::int64_t number) {
    const auto bits = static_cast<std::uint64_t>(number);
    for (int i = 0; i < 8; ++i) mix(static_cast<unsigned char>(bits >> (8 * i)));
  }
  /// The digest of what was added; never 0 (0 means "no digest").
  std::uint64_t value() const { return value_ == 0 ? 1 : value_; }

 private:
  void mix(unsigned char byte) { value_ = (value_ ^ byte) * 0x100000001b3ULL; }

  std::uint64_t value_ = 0xcbf29ce484222325ULL;
};

}  // namespace agents
}  // namespace ppp
