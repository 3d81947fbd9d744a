// libFuzzer target for the simulator's side of the batch protocol: the input is a stream of ROS-serialised
// ppp_msgs/MoveBatch messages (one after another, as a subscriber receives them, without TCPROS's frame lengths),
// each the answer to the next batch of a fresh AgentLane (an explorer's runs on two small PPPs). Each message is
// deserialised as roscpp does (see ppp_agents/fuzz/ros_wire.hpp for the inputs refused first), decoded
// (decodeMoves) and applied to the lane, as lane_runner does. decodeMoves must never throw and must answer every
// move or, for arrays that differ in length, none with invalid_action; the lane must end each run once, with a
// reason the protocol knows and a pass exactly when it reached the goal, its count of remaining runs going down
// by the runs ended. Anything else, a crash or a sanitizer report is a finding.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "ppp_agents/protocol/batch_codec.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/fuzz_finding.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_agents/agent_lane.hpp"
#include "ppp_simulator/experiment_runner.hpp"
#include "ros_wire.hpp"

namespace {

using ppp::fuzz::finding;
namespace protocol = ppp::protocol;

/// The lane's PPPs: two small hand-made ones, prepared once.
const std::vector<ppp::agents::PreparedSet>& laneSets() {
  static const std::vector<ppp::agents::PreparedSet> sets = [] {
    std::vector<ppp::Problem> problems;
    for (int i = 0; i < 2; ++i) {
      ppp::Problem p = ppp::Problem::empty(6, 5, 2);
      p.obstacles.push_back(ppp::Obstacle{ppp::Shape::HorizontalBar, i, 2, 4, 1});
      ppp::setMetadata(&p.metadata, "id", "ppp_00" + std::to_string(i));
      ppp::setMetadata(&p.metadata, "fitness", "turns");
      ppp::setMetadata(&p.metadata, "fitness_value", "1");
      problems.push_back(p);
    }
    return std::vector<ppp::agents::PreparedSet>{
        ppp::agents::prepareSet("fuzz", ppp::generator::problemSetFromProblems(problems, {}, "fuzz"), ppp::EpisodeOptions{})};
  }();
  return sets;
}

/// A fresh lane of `type`'s runs: 2 per PPP, a budget of 12 moves, batches of up to 3 episodes.
ppp::agents::AgentLane lane(const std::string& type) {
  return ppp::simulator::experimentLane({type, type}, ppp::EpisodeOptions{12, 2}, laneSets(), 1, 2, {}, 3);
}

/// Walks one MoveBatch (ppp_msgs/msg/MoveBatch.msg); false when it does not fit in the bytes left.
bool walkMoveBatch(ppp::fuzz::WireWalker* w) {
  std::uint32_t failures = 0;
  const std::size_t least_failure = 4 + 4 + 4;  // episode, reason length, diagnosis length
  if (!w->header() || !w->array(1) || !w->fixed(4) || !w->array(4) || !w->array(4) || !w->array(1) ||
      !w->array(8) || !w->length(least_failure, &failures)) {
    return false;
  }
  for (std::uint32_t i = 0; i < failures; ++i) {
    if (!w->fixed(4) || !w->array(1) || !w->array(1)) return false;
  }
  return true;
}

/// Whether `reason` is one a run may end with when the moves come from an agent node.
bool knownReason(const std::string& reason) {
  namespace r = ppp::reason;
  return reason == r::kGoalReached || reason == r::kBudgetExhausted || reason == r::kTimeout ||
         reason == r::kInvalidAction || ppp::reason::agentReportedReason(reason) != nullptr;
}

/// decodeMoves answers every move of a well-formed message and none of a malformed one.
void checkDecoded(const ppp_msgs::MoveBatch& message, const protocol::DecodedMoves& decoded) {
  const std::size_t n = message.episodes.size();
  if (message.steps.size() != n || message.actions.size() != n) {
    if (!decoded.moves.empty() || std::strcmp(decoded.missing_reason, ppp::reason::kInvalidAction) != 0) {
      finding("move_batch_fuzz", "a malformed MoveBatch answered moves", decoded.fault);
    }
    return;
  }
  if (decoded.moves.size() != n) finding("move_batch_fuzz", "moves lost in decoding", decoded.fault);
  for (std::size_t i = 0; i < n; ++i) {
    const protocol::MoveReply& m = decoded.moves[i];
    if (m.episode != message.episodes[i] || m.step != message.steps[i] || m.action != message.actions[i]) {
      finding("move_batch_fuzz", "a move changed in decoding", "");
    }
    if (m.failure != nullptr && !knownReason(m.failure)) finding("move_batch_fuzz", "unknown failure", m.failure);
    if (m.diagnosis != nullptr && (m.failure == nullptr || std::strcmp(m.failure, ppp::reason::kNoPath) != 0)) {
      finding("move_batch_fuzz", "a diagnosis without no_path", m.diagnosis);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ppp::agents::AgentLane played = lane("explorer");
  std::set<std::pair<std::string, int>> ended;  // (problem, run)
  std::vector<protocol::ScanRequest> scans;
  for (std::size_t at = 0; at < size && !played.finished();) {
    ppp::fuzz::WireWalker walker(data + at, size - at);
    if (!walkMoveBatch(&walker)) return 0;
    ppp_msgs::MoveBatch message;
    ppp::fuzz::deserializeWalked("move_batch_fuzz", data + at, walker.offset(), &message);
    at += walker.offset();
    played.scans(&scans);
    const protocol::DecodedMoves decoded = protocol::decodeMoves(message);
    checkDecoded(message, decoded);
    const long before = played.remaining();
    const std::vector<ppp::agents::EpisodeResult> results = played.answer(decoded.moves, decoded.missing_reason);
    if (played.remaining() != before - static_cast<long>(results.size())) {
      finding("move_batch_fuzz", "the lane's remaining runs do not add up", std::to_string(results.size()));
    }
    for (const ppp::agents::EpisodeResult& r : results) {
      if (!ended.emplace(r.problem, r.run).second) finding("move_batch_fuzz", "a run ended twice", r.problem);
      if (!knownReason(r.reason)) finding("move_batch_fuzz", "a run ended for an unknown reason", r.reason);
      if (r.passed != (r.reason == ppp::reason::kGoalReached)) finding("move_batch_fuzz", "pass", r.reason);
      // Every row the lane makes, its diagnosis included, is one results.csv reads back as it was written.
      std::string line;
      ppp::agents::appendCsvRow(r, &line);
      line.pop_back();
      try {
        if (ppp::agents::toCsvFields(ppp::agents::parseCsvRow(line, "fuzz.csv", 2)) != ppp::agents::toCsvFields(r)) {
          finding("move_batch_fuzz", "a row changed when read back", line);
        }
      } catch (const ppp::ParseError& e) {
        finding("move_batch_fuzz", "a row the lane made is refused", std::string(e.what()) + ": " + line);
      }
    }
  }
  return 0;
}
