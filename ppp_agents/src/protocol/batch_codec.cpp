#include "ppp_agents/protocol/batch_codec.hpp"

#include <algorithm>

#include "ppp_core/diagnosis.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {
namespace protocol {

// The wire's constants, as the generated message headers declare them, are the core's values: a change on either
// side stops the build here instead of moving agents the wrong way.
static_assert(ppp_msgs::MoveBatch::STAY == static_cast<int>(Action::Stay), "MoveBatch STAY");
static_assert(ppp_msgs::MoveBatch::NORTH == static_cast<int>(Action::North), "MoveBatch NORTH");
static_assert(ppp_msgs::MoveBatch::EAST == static_cast<int>(Action::East), "MoveBatch EAST");
static_assert(ppp_msgs::MoveBatch::SOUTH == static_cast<int>(Action::South), "MoveBatch SOUTH");
static_assert(ppp_msgs::MoveBatch::WEST == static_cast<int>(Action::West), "MoveBatch WEST");
static_assert(ppp_msgs::MoveBatch::NORTH_EAST == static_cast<int>(Action::NorthEast), "MoveBatch NORTH_EAST");
static_assert(ppp_msgs::MoveBatch::SOUTH_EAST == static_cast<int>(Action::SouthEast), "MoveBatch SOUTH_EAST");
static_assert(ppp_msgs::MoveBatch::SOUTH_WEST == static_cast<int>(Action::SouthWest), "MoveBatch SOUTH_WEST");
static_assert(ppp_msgs::MoveBatch::NORTH_WEST == static_cast<int>(Action::NorthWest), "MoveBatch NORTH_WEST");
static_assert(ppp_msgs::MoveBatch::NORTH_WEST + 1 == kOctileActionCount, "MoveBatch: one constant per action");

ppp_msgs::GridCell toGridCell(Cell cell) {
  ppp_msgs::GridCell m;
  m.x = cell.x;
  m.y = cell.y;
  return m;
}

void ScanBatchWriter::begin(std::size_t count, int range, bool window) {
  ppp_msgs::ScanBatch& m = *message_;
  m.range = count == 0 ? 0 : static_cast<std::uint8_t>(range);
  words_ = count == 0 || !window ? 0 : static_cast<std::size_t>(windowWords(range));
  m.starts.clear();
  m.episodes.clear();
  m.steps.clear();
  m.positions.clear();
  m.bumped.clear();
  m.free_cells.clear();
  m.obstacle_cells.clear();
  m.episodes.reserve(count);
  m.steps.reserve(count);
  m.positions.reserve(count);
  m.bumped.reserve(count);
  m.free_cells.reserve(count * words_);
  m.obstacle_cells.reserve(count * words_);
}

void ScanBatchWriter::add(ScanRequest& r) {
  ppp_msgs::ScanBatch& m = *message_;
  m.episodes.push_back(r.episode);
  m.steps.push_back(static_cast<std::uint32_t>(r.step));
  m.positions.push_back(toGridCell(r.position));
  m.bumped.push_back(r.bumped ? 1 : 0);
  if (words_ == 1) {  // the usual window of at most 64 cells: one word each, no copy loop
    m.free_cells.push_back(r.free_cells[0]);
    m.obstacle_cells.push_back(r.obstacle_cells[0]);
  } else {
    m.free_cells.insert(m.free_cells.end(), r.free_cells.begin(), r.free_cells.begin() + words_);
    m.obstacle_cells.insert(m.obstacle_cells.end(), r.obstacle_cells.begin(), r.obstacle_cells.begin() + words_);
  }
  if (!r.start) return;
  ppp_msgs::EpisodeStart start;
  start.episode = r.episode;
  start.width = static_cast<std::uint32_t>(r.start->width);
  start.height = static_cast<std::uint32_t>(r.start->height);
  start.start = toGridCell(r.start->start);
  start.goal = toGridCell(r.start->goal);
  start.agent_seed = r.start->agent_seed;
  start.prior_map = std::move(r.start->prior_map);
  start.connectivity = static_cast<std::uint8_t>(neighbours(r.start->connectivity));
  m.starts.push_back(std::move(start));
}

void encodeScans(const std::vector<ScanRequest>& scans, ppp_msgs::ScanBatch* message) {
  ScanBatchWriter writer(message);
  writer.begin(scans.size(), scans.empty() ? 0 : scans[0].range, !scans.empty() && scans[0].window);
  for (ScanRequest scan : scans) writer.add(scan);
}

std::string checkScanBatch(const ppp_msgs::ScanBatch& batch, bool reads_window, std::string* what) {
  const std::size_t n = batch.episodes.size();
  if (batch.steps.size() != n || batch.positions.size() != n || batch.bumped.size() != n) {
    *what = "episodes, steps, positions and bumped differ in length (" + std::to_string(n) + ", " +
            std::to_string(batch.steps.size()) + ", " + std::to_string(batch.positions.size()) + ", " +
            std::to_string(batch.bumped.size()) + ")";
    return "batch";
  }
  if (n > 0 && (batch.range < 1 || batch.range > kMaxSensorRange)) {
    *what = "range " + std::to_string(batch.range) + " is outside [1, " + std::to_string(kMaxSensorRange) + "]";
    return "range";
  }
  if (!reads_window) return "";
  const std::size_t words = n == 0 ? 0 : static_cast<std::size_t>(windowWords(batch.range));
  if (batch.free_cells.size() != n * words || batch.obstacle_cells.size() != n * words) {
    *what = "expected " + std::to_string(n) + " windows of " + std::to_string(words) + " mask words, got " +
            std::to_string(batch.free_cells.size()) + " free and " + std::to_string(batch.obstacle_cells.size()) +
            " obstacle words";
    return "cells";
  }
  const std::size_t cells = n == 0 ? 0 : windowCells(batch.range);
  const std::uint64_t past = cells % 64 == 0 ? 0 : ~std::uint64_t{0} << (cells % 64);  // bits past the window
  for (std::size_t k = words - 1; k < n * words; k += words) {
    if (((batch.free_cells[k] | batch.obstacle_cells[k]) & past) != 0) {
      *what = "the window of scan " + std::to_string(k / words) + " has bits past its last cell";
      return "cells";
    }
  }
  return "";
}

EpisodeStart decodeEpisodeStart(const ppp_msgs::EpisodeStart& message) {
  const auto side_ok = [](std::uint32_t side) { return side >= kMinGridSide && side <= kMaxGridSide; };
  if (!side_ok(message.width) || !side_ok(message.height)) {
    throw InvalidArgument("size", "the map size " + std::to_string(message.width) + "x" +
                                      std::to_string(message.height) + " is outside [" +
                                      std::to_string(kMinGridSide) + ", " + std::to_string(kMaxGridSide) + "]");
  }
  EpisodeStart start;
  start.width = static_cast<int>(message.width);
  start.height = static_cast<int>(message.height);
  start.start = toCell(message.start);
  start.goal = toCell(message.goal);
  start.agent_seed = message.agent_seed;
  start.prior_map = message.prior_map;
  const int model = message.connectivity == 0 ? neighbours(Connectivity::Four) : message.connectivity;
  if (model != neighbours(Connectivity::Four) && model != neighbours(Connectivity::Eight)) {
    throw InvalidArgument("connectivity", "expected 4 or 8 (0: 4), got " + std::to_string(message.connectivity));
  }
  start.connectivity = static_cast<Connectivity>(model);
  requireOnGrid(start.start, start.width, start.height, "start");
  requireOnGrid(start.goal, start.width, start.height, "goal");
  priorGrid(start);  // checks the prior map
  return start;
}

std::vector<ScanRequest> decodeScans(const ppp_msgs::ScanBatch& batch, bool reads_window) {
  std::string what;
  const std::string fault = checkScanBatch(batch, reads_window, &what);
  if (!fault.empty()) throw InvalidArgument(fault, what);
  std::vector<ScanRequest> scans(batch.episodes.size());
  const std::size_t words = scans.empty() ? 0 : static_cast<std::size_t>(windowWords(batch.range));
  for (std::size_t i = 0; i < scans.size(); ++i) {
    ScanRequest& s = scans[i];
    s.episode = batch.episodes[i];
    s.step = static_cast<int>(batch.steps[i]);
    s.position = toCell(batch.positions[i]);
    s.bumped = batch.bumped[i] != 0;
    s.range = batch.range;
    s.window = reads_window;
    if (!reads_window) continue;
    std::copy_n(batch.free_cells.begin() + i * words, words, s.free_cells.begin());
    std::copy_n(batch.obstacle_cells.begin() + i * words, words, s.obstacle_cells.begin());
  }
  for (const ppp_msgs::EpisodeStart& m : batch.starts) {
    bool found = false;
    for (ScanRequest& s : scans) {
      if (s.episode != m.episode) continue;
      s.start = decodeEpisodeStart(m);
      s.goal = s.start->goal;
      found = true;
    }
    if (!found) throw InvalidArgument("starts", "episode " + std::to_string(m.episode) + " starts without a scan");
  }
  return scans;
}

ppp_msgs::MoveBatch encodeMoves(const std::string& agent, std::uint32_t batch, const std::vector<MoveReply>& moves) {
  ppp_msgs::MoveBatch m;
  m.agent = agent;
  m.batch = batch;
  m.episodes.resize(moves.size());
  m.steps.resize(moves.size());
  m.actions.resize(moves.size());
  for (std::size_t i = 0; i < moves.size(); ++i) {
    m.episodes[i] = moves[i].episode;
    m.steps[i] = moves[i].step;
    m.actions[i] = static_cast<std::uint8_t>(moves[i].action);
    if (moves[i].failure == nullptr) continue;
    ppp_msgs::EpisodeFailure failure;
    failure.episode = moves[i].episode;
    failure.reason = moves[i].failure;
    if (moves[i].diagnosis != nullptr) failure.diagnosis = moves[i].diagnosis;
    m.failures.push_back(failure);
  }
  const bool states = std::any_of(moves.begin(), moves.end(), [](const MoveReply& r) { return r.state != 0; });
  if (states) {
    m.states.resize(moves.size());
    for (std::size_t i = 0; i < moves.size(); ++i) m.states[i] = moves[i].state;
  }
  return m;
}

DecodedMoves decodeMoves(const ppp_msgs::MoveBatch& message) {
  DecodedMoves decoded;
  const std::size_t n = message.episodes.size();
  if (message.steps.size() != n || message.actions.size() != n) {
    decoded.missing_reason = reason::kInvalidAction;
    decoded.fault = "a MoveBatch whose episodes, steps and actions differ in length (" + std::to_string(n) + ", " +
                    std::to_string(message.steps.size()) + ", " + std::to_string(message.actions.size()) + ")";
    return decoded;
  }
  decoded.moves.resize(n);
  for (std::size_t i = 0; i < n; ++i) decoded.moves[i] = {message.episodes[i], message.steps[i], message.actions[i]};
  if (message.states.size() == n) {
    for (std::size_t i = 0; i < n; ++i) decoded.moves[i].state = message.states[i];
  } else if (!message.states.empty()) {
    decoded.fault = "a MoveBatch with " + std::to_string(message.states.size()) + " states for " +
                    std::to_string(n) + " moves: its states are ignored";
  }
  for (const ppp_msgs::EpisodeFailure& f : message.failures) {
    const char* why = reason::agentReportedReason(f.reason);
    if (why == nullptr) {
      decoded.fault = "an episode given up for an unknown reason '" + f.reason + "': recorded as invalid_action";
      why = reason::kInvalidAction;
    }
    const char* kind = nullptr;
    if (!f.diagnosis.empty()) {
      kind = diagnosis::kindNamed(f.diagnosis);
      const bool fits = f.reason == reason::kNoPath &&
                        (f.diagnosis == diagnosis::kMissedRoute || f.diagnosis == diagnosis::kNoRoute);
      if (!fits) {
        decoded.fault = "a " + f.reason + " failure with the diagnosis '" + f.diagnosis +
                        "' (only no_path takes one: missed_route or no_route): the diagnosis is ignored";
        kind = nullptr;
      }
    }
    for (MoveReply& m : decoded.moves) {
      if (m.episode == f.episode) {
        m.failure = why;
        m.diagnosis = kind;
      }
    }
  }
  return decoded;
}

}  // namespace protocol
}  // namespace ppp
