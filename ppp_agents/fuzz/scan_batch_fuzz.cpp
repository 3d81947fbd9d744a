// libFuzzer target for the agent node's side of the batch protocol: the input is a stream of ROS-serialised
// ppp_msgs/ScanBatch messages (one after another, as a subscriber receives them, without TCPROS's frame lengths).
// Each is deserialised as roscpp does (see ros_wire.hpp for the inputs refused first), checked and decoded
// (checkScanBatch, decodeScans, decodeEpisodeStart) and answered, as agent_node does, by a BatchResponder of each
// of several agent types fed the whole stream: astar (given the prior map of each EpisodeStart), explorer with a
// 5x5 memory, long_term_explorer and random (which reads no window). Decoding must return or throw
// InvalidArgument; a responder must never throw and must answer every scan, echoing the batch number, its
// episode and step, with an action or kRejectedAction (for every scan of a malformed batch); its answer must
// decode without fault. Anything else, a crash or a sanitizer report is a finding. A batch starting an episode on a
// map of more than 64 x 64 cells is decoded and checked but not answered: each started episode's agent keeps a
// map of width x height cells (16 MB at 4096 x 4096, the largest), and with such inputs the target ran at about
// 1,200 executions per second instead of 5,000; the agents' play on large maps is the agents' tests' business.

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <ros/console.h>

#include "ppp_core/action.hpp"
#include "ppp_agents/protocol/batch_responder.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/fuzz_finding.hpp"
#include "ros_wire.hpp"

namespace {

using ppp::fuzz::finding;
namespace protocol = ppp::protocol;

/// Walks one ScanBatch (ppp_msgs/msg/ScanBatch.msg); false when it does not fit in the bytes left.
bool walkScanBatch(ppp::fuzz::WireWalker* w) {
  std::uint32_t starts = 0;
  // episode, size, start, goal, seed, prior_map length, connectivity
  const std::size_t least_start = 4 + 4 + 4 + 8 + 8 + 8 + 4 + 1;
  if (!w->header() || !w->array(1) || !w->fixed(4) || !w->fixed(1) || !w->length(least_start, &starts)) return false;
  for (std::uint32_t i = 0; i < starts; ++i) {
    if (!w->fixed(4 + 4 + 4 + 8 + 8 + 8) || !w->array(1) || !w->fixed(1)) return false;
  }
  return w->array(4) && w->array(4) && w->array(8) && w->array(1) && w->array(8) && w->array(8);
}

/// decodeScans returns or throws InvalidArgument, agreeing with checkScanBatch.
void checkDecoding(const ppp_msgs::ScanBatch& batch, bool reads_window) {
  std::string what;
  const std::string fault = protocol::checkScanBatch(batch, reads_window, &what);
  try {
    const std::vector<protocol::ScanRequest> scans = protocol::decodeScans(batch, reads_window);
    if (!fault.empty()) finding("scan_batch_fuzz", "decodeScans accepted a batch checkScanBatch refuses", what);
    if (scans.size() != batch.episodes.size()) finding("scan_batch_fuzz", "decodeScans lost scans", "");
  } catch (const ppp::InvalidArgument&) {
  }
}

/// The responder's answer to `batch` is complete and well formed; diagonal moves only in episodes whose start
/// said connectivity 8 (`connectivity`: the last start's value per episode id).
void checkAnswer(const ppp_msgs::ScanBatch& batch, const ppp_msgs::MoveBatch& moves, const std::string& agent,
                 bool malformed, const std::map<std::uint32_t, ppp::Connectivity>& connectivity) {
  const std::size_t n = batch.episodes.size();
  if (moves.agent != agent || moves.batch != batch.batch) {
    finding("scan_batch_fuzz", "agent or batch not echoed", agent);
  }
  if (moves.episodes != batch.episodes || moves.steps.size() != n || moves.actions.size() != n) {
    finding("scan_batch_fuzz", "not one move per scan, in order", agent);
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (moves.steps[i] != (i < batch.steps.size() ? batch.steps[i] : 0)) finding("scan_batch_fuzz", "step", agent);
    const std::uint8_t action = moves.actions[i];
    const auto started = connectivity.find(batch.episodes[i]);
    const ppp::Connectivity model = started == connectivity.end() ? ppp::Connectivity::Four : started->second;
    if (!ppp::isAction(action, model) && action != protocol::kRejectedAction) {
      finding("scan_batch_fuzz", "an action that is no action and no rejection", agent);
    }
    if (malformed && action != protocol::kRejectedAction) {
      finding("scan_batch_fuzz", "a scan of a malformed batch was acted on", agent);
    }
  }
  const protocol::DecodedMoves decoded = protocol::decodeMoves(moves);
  if (!decoded.fault.empty() || decoded.moves.size() != n) finding("scan_batch_fuzz", decoded.fault.c_str(), agent);
}

/// Largest map, in cells, whose episodes the responders are given (see the top of the file).
constexpr std::uint64_t kMostMapCells = 64 * 64;

/// Whether every episode `batch` starts is on a map of at most kMostMapCells.
bool smallMaps(const ppp_msgs::ScanBatch& batch) {
  for (const ppp_msgs::EpisodeStart& start : batch.starts) {
    if (static_cast<std::uint64_t>(start.width) * start.height > kMostMapCells) return false;
  }
  return true;
}

/// The agent configurations answering the stream.
const std::vector<ppp::agents::AgentConfig>& configs() {
  static const std::vector<ppp::agents::AgentConfig> list = {{"astar", "astar"},
                                                             {"explorer_5x5", "explorer", 5},
                                                             {"long_term_explorer", "long_term_explorer"},
                                                             {"random", "random"}};
  return list;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // The responders log each kind of rejected scan once per responder, that is once per input here: not wanted.
  ros::console::set_logger_level(ROSCONSOLE_DEFAULT_NAME, ros::console::levels::Error);
  ros::console::notifyLoggerLevelsChanged();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::unique_ptr<protocol::BatchResponder>> responders;
  for (const ppp::agents::AgentConfig& config : configs()) {
    responders.push_back(std::make_unique<protocol::BatchResponder>(config));
  }
  std::map<std::uint32_t, ppp::Connectivity> connectivity;
  for (std::size_t at = 0; at < size;) {
    ppp::fuzz::WireWalker walker(data + at, size - at);
    if (!walkScanBatch(&walker)) return 0;
    ppp_msgs::ScanBatch batch;
    ppp::fuzz::deserializeWalked("scan_batch_fuzz", data + at, walker.offset(), &batch);
    at += walker.offset();
    checkDecoding(batch, true);
    checkDecoding(batch, false);
    if (!smallMaps(batch)) continue;
    for (const ppp_msgs::EpisodeStart& start : batch.starts) {
      connectivity[start.episode] = start.connectivity == ppp::neighbours(ppp::Connectivity::Eight) ? ppp::Connectivity::Eight
                                                                                                  : ppp::Connectivity::Four;
    }
    for (std::size_t r = 0; r < responders.size(); ++r) {
      const ppp::agents::AgentConfig& config = configs()[r];
      std::string what;
      const bool malformed = !protocol::checkScanBatch(batch, ppp::agents::readsScanWindow(config), &what).empty();
      checkAnswer(batch, responders[r]->answer(batch), config.name, malformed, connectivity);
    }
  }
  return 0;
}
