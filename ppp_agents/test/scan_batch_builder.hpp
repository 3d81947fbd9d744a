#pragma once

// Test helper: scans written one episode at a time and packed into a ppp_msgs::ScanBatch the way the
// simulator node packs them.

#include <cstdint>
#include <optional>
#include <vector>

#include "ppp_core/grid.hpp"
#include "ppp_msgs/ScanBatch.h"

namespace ppp {
namespace agents {
namespace test {

/// A grid cell as a message.
inline ppp_msgs::GridCell cellMessage(Cell c) {
  ppp_msgs::GridCell m;
  m.x = c.x;
  m.y = c.y;
  return m;
}

/// One episode's scan; `start` is set for the episode's first batch.
struct TestScan {
  std::uint32_t episode = 0;                    ///< Episode id.
  std::uint32_t step = 0;                       ///< Step number.
  Cell position;                                ///< The agent's cell.
  bool bumped = false;                          ///< The last move bumped.
  std::vector<std::int8_t> cells;               ///< The window (may be empty for agents that read none).
  std::optional<ppp_msgs::EpisodeStart> start;  ///< Sent with the scan when set.
};

/// The batch holding `scans` in order, with sensor range `range`.
inline ppp_msgs::ScanBatch packBatch(std::uint32_t number, int range, const std::vector<TestScan>& scans) {
  ppp_msgs::ScanBatch batch;
  batch.batch = number;
  batch.range = static_cast<std::uint8_t>(range);
  for (const TestScan& s : scans) {
    if (s.start) batch.starts.push_back(*s.start);
    batch.episodes.push_back(s.episode);
    batch.steps.push_back(s.step);
    batch.positions.push_back(cellMessage(s.position));
    batch.bumped.push_back(s.bumped ? 1 : 0);
    batch.cells.insert(batch.cells.end(), s.cells.begin(), s.cells.end());
  }
  return batch;
}

}  // namespace test
}  // namespace agents
}  // namespace ppp
