#pragma once

#include <string>
#include <vector>

#include "ppp_agents/protocol/batch_types.hpp"
#include "ppp_msgs/EpisodeStart.h"
#include "ppp_msgs/MoveBatch.h"
#include "ppp_msgs/ScanBatch.h"

namespace ppp {
namespace protocol {

// The batch protocol's messages: what the simulator sends (encodeScans) and the agent side reads
// (checkScanBatch, decodeEpisodeStart, decodeScans), what the agent side answers (encodeMoves) and the
// simulator reads (decodeMoves). Every check of a message is here.

/// A message cell as a grid cell (both y down).
inline Cell toCell(const ppp_msgs::GridCell& cell) { return Cell{static_cast<int>(cell.x), static_cast<int>(cell.y)}; }

/// A grid cell as a message cell.
ppp_msgs::GridCell toGridCell(Cell cell);

/// Writes a lane's scans straight into a ScanBatch (one batch of one agent), reusing its buffers; the header, agent
/// and batch number are left to the caller.
class ScanBatchWriter : public ScanSink {
 public:
  explicit ScanBatchWriter(ppp_msgs::ScanBatch* message) : message_(message) {}
  void begin(std::size_t count, int range, bool window) override;
  void add(ScanRequest& scan) override;

 private:
  ppp_msgs::ScanBatch* message_;
  std::size_t words_ = 0;  // mask words per scan: 0 without windows
};

/// Fills `message` with `scans`, as a ScanBatchWriter does.
void encodeScans(const std::vector<ScanRequest>& scans, ppp_msgs::ScanBatch* message);

/// Checks that a batch's per-scan arrays agree in length, its range is a sensor range and, for an agent that
/// reads windows, that it holds one window per scan. Returns the field at fault ("batch", "range", "cells")
/// and sets `what`, or returns "" when the batch is well formed.
std::string checkScanBatch(const ppp_msgs::ScanBatch& batch, bool reads_window, std::string* what);

/// An EpisodeStart as a protocol::EpisodeStart, checked. @throws InvalidArgument naming the field ("size",
/// "start", "goal", "prior_map").
EpisodeStart decodeEpisodeStart(const ppp_msgs::EpisodeStart& start);

/// Every scan of a batch, each with its start when the batch starts its episode (and then its goal); windows
/// stay empty when the batch carries none. @throws InvalidArgument naming the field at fault.
std::vector<ScanRequest> decodeScans(const ppp_msgs::ScanBatch& batch, bool reads_window);

/// The answer to batch number `batch` of agent `agent`: one move per reply, in order, and the episodes given up.
ppp_msgs::MoveBatch encodeMoves(const std::string& agent, std::uint32_t batch, const std::vector<MoveReply>& moves);

/// What a MoveBatch says, for the simulator's lane.
struct DecodedMoves {
  std::vector<MoveReply> moves;             ///< One per move of the batch, failures attached.
  const char* missing_reason = reason::kTimeout;  ///< Why an episode the batch does not answer fails.
  std::string fault;                        ///< What was wrong with the batch ("" when nothing was).
};

/// Reads an answer. A batch whose arrays differ in length answers nothing and fails every episode as
/// invalid_action; a failure reason an agent may not give is recorded as invalid_action. Never throws.
DecodedMoves decodeMoves(const ppp_msgs::MoveBatch& message);

}  // namespace protocol
}  // namespace ppp
