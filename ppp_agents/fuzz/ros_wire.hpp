#pragma once

// The batch protocol's libFuzzer targets (scan_batch, move_batch) feed ROS-serialised messages to the code a node
// runs on a message. roscpp's deserializer (ros/serialization.h) resizes an array to its 4-byte length prefix
// before it checks that the bytes are there, and computes sizeof(element) * length in 32 bits, so an input of a
// few bytes can ask for a vector of 4 GB: roscpp's behaviour, not ours, which any roscpp subscriber shares (a
// TCPROS frame bounds the message, not its arrays). So the targets refuse an input whose length prefixes claim
// more elements than the bytes left could hold: they walk the message's layout (its .msg file) with WireWalker
// before deserialising. A message the walk accepts deserialises without overrun; if roscpp disagrees the target
// reports it.

#include <cstddef>
#include <cstdint>
#include <cstring>

#include <ros/serialization.h>

#include "ppp_core/fuzz_finding.hpp"

namespace ppp {
namespace fuzz {

/// Walks serialised ROS message fields, checking every length prefix against the bytes left.
class WireWalker {
 public:
  /// Walks `size` bytes from `data`.
  WireWalker(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  /// A fixed-size field of `bytes`; false when the input ends first.
  bool fixed(std::size_t bytes) {
    if (bytes > size_ - at_) return false;
    at_ += bytes;
    return true;
  }

  /// An array (or string) of fixed-size elements of `element_bytes` each; false when its length prefix claims
  /// more than the bytes left.
  bool array(std::size_t element_bytes) {
    std::uint32_t count = 0;
    return length(element_bytes, &count) && fixed(element_bytes * count);
  }

  /// The length prefix of an array of variable-size elements of at least `least_bytes` each, into `count`;
  /// false when even that many elements of the least size cannot fit in the bytes left.
  bool length(std::size_t least_bytes, std::uint32_t* count) {
    if (sizeof(std::uint32_t) > size_ - at_) return false;
    std::memcpy(count, data_ + at_, sizeof(std::uint32_t));  // little-endian, as ROS writes it
    at_ += sizeof(std::uint32_t);
    return static_cast<std::size_t>(*count) * least_bytes <= size_ - at_;
  }

  /// A std_msgs/Header: seq, stamp, frame_id.
  bool header() { return fixed(4) && fixed(8) && array(1); }

  /// Bytes walked so far.
  std::size_t offset() const { return at_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

/// Deserialises `message` from exactly `size` bytes at `data` (a span WireWalker accepted); roscpp running out of
/// bytes there is a finding of `target`, as is a message shorter than the span.
template <typename Message>
void deserializeWalked(const char* target, const std::uint8_t* data, std::size_t size, Message* message) {
  ros::serialization::IStream stream(const_cast<std::uint8_t*>(data), static_cast<std::uint32_t>(size));
  try {
    ros::serialization::deserialize(stream, *message);
  } catch (const ros::serialization::StreamOverrunException& e) {
    finding(target, "roscpp ran out of bytes in a message whose layout was walked", e.what());
  }
  if (stream.getLength() != 0) finding(target, "a walked message left bytes over", "");
}

}  // namespace fuzz
}  // namespace ppp
