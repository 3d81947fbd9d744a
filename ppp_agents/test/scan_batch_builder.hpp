#pragma once

// Test helper: scans written one episode at a time and packed into a ppp_msgs::ScanBatch by the protocol's own
// encoder, as the simulator node packs them.

#include <cstdint>
#include <vector>

#include "ppp_agents/protocol/batch_codec.hpp"

namespace ppp {
namespace agents {
namespace test {

/// One episode's scan; `start` is set for the episode's first batch.
using TestScan = protocol::ScanRequest;

/// The batch holding `scans` in order, with sensor range `range`.
inline ppp_msgs::ScanBatch packBatch(std::uint32_t number, int range, std::vector<TestScan> scans) {
  for (TestScan& s : scans) s.range = range;
  ppp_msgs::ScanBatch batch;
  protocol::encodeScans(scans, &batch);
  batch.batch = number;
  batch.range = static_cast<std::uint8_t>(range);
  return batch;
}

}  // namespace test
}  // namespace agents
}  // namespace ppp
