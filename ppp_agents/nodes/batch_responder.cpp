#include "batch_responder.hpp"

#include <ros/console.h>

#include <exception>
#include <memory>

#include "ppp_core/error.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {
namespace agents {

namespace {

Cell toCell(const ppp_msgs::GridCell& cell) { return Cell{static_cast<int>(cell.x), static_cast<int>(cell.y)}; }

std::string cellText(Cell c) { return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")"; }

/// Throws InvalidArgument naming `field` unless `cell` lies on a width x height grid.
void requireOnGrid(Cell cell, int width, int height, const char* field) {
  if (cell.x < 0 || cell.y < 0 || cell.x >= width || cell.y >= height) {
    throw InvalidArgument(field, cellText(cell) + " is off the " + std::to_string(width) + "x" +
                                     std::to_string(height) + " map");
  }
}

}  // namespace

BatchResponder::BatchResponder(const AgentConfig& config)
    : config_(config), reads_window_(readsScanWindow(config)), host_(config) {}

ppp_msgs::MoveBatch BatchResponder::answer(const ppp_msgs::ScanBatch& batch) {
  ++round_;
  const std::size_t n = batch.episodes.size();
  ppp_msgs::MoveBatch moves;
  moves.agent = config_.name;
  moves.batch = batch.batch;
  moves.episodes = batch.episodes;
  moves.steps.resize(n);
  moves.actions.resize(n, kRejectedAction);
  std::string what;
  const std::string fault = checkShape(batch, &what);
  if (!fault.empty()) {
    for (std::size_t i = 0; i < n; ++i) {
      moves.steps[i] = i < batch.steps.size() ? batch.steps[i] : 0;
      reject(batch.episodes[i], moves.steps[i], fault, what);
    }
    return moves;
  }
  failed_starts_.clear();
  for (const ppp_msgs::EpisodeStart& s : batch.starts) {
    try {
      start(s);
    } catch (const InvalidArgument& e) {
      failed_starts_.emplace(s.episode, e);  // rejected with the episode's scan
    }
  }
  const std::size_t window = static_cast<std::size_t>(2 * batch.range + 1) * (2 * batch.range + 1);
  if (!reads_window_) unknown_window_.assign(window, kScanUnknown);
  for (std::size_t i = 0; i < n; ++i) {
    moves.steps[i] = batch.steps[i];
    const std::int8_t* cells = reads_window_ ? batch.cells.data() + i * window : unknown_window_.data();
    try {
      moves.actions[i] = act(batch, i, cells);
    } catch (const InvalidArgument& e) {
      reject(batch.episodes[i], batch.steps[i], e.name(), e.what());
    } catch (const std::exception& e) {
      reject(batch.episodes[i], batch.steps[i], "agent", e.what());
    }
  }
  // Episodes the simulator no longer sends are over.
  for (auto it = episodes_.begin(); it != episodes_.end();) {
    if (it->second.round == round_) {
      ++it;
      continue;
    }
    host_.finish(it->first);
    it = episodes_.erase(it);
  }
  return moves;
}

std::string BatchResponder::checkShape(const ppp_msgs::ScanBatch& batch, std::string* what) const {
  const std::size_t n = batch.episodes.size();
  if (batch.steps.size() != n || batch.positions.size() != n || batch.bumped.size() != n) {
    *what = "episodes, steps, positions and bumped differ in length (" + std::to_string(n) + ", " +
            std::to_string(batch.steps.size()) + ", " + std::to_string(batch.positions.size()) + ", " +
            std::to_string(batch.bumped.size()) + ")";
    return "batch";
  }
  if (batch.range < 1 || batch.range > kMaxSensorRange) {
    *what = "range " + std::to_string(batch.range) + " is outside [1, " + std::to_string(kMaxSensorRange) + "]";
    return "range";
  }
  const std::size_t window = static_cast<std::size_t>(2 * batch.range + 1) * (2 * batch.range + 1);
  if (reads_window_ && batch.cells.size() != n * window) {
    *what = "expected " + std::to_string(n) + " windows of " + std::to_string(window) + " cells, got " +
            std::to_string(batch.cells.size()) + " cells";
    return "cells";
  }
  return "";
}

std::uint8_t BatchResponder::act(const ppp_msgs::ScanBatch& batch, std::size_t i, const std::int8_t* window) {
  const std::uint32_t id = batch.episodes[i];
  const std::uint32_t step = batch.steps[i];
  auto it = episodes_.find(id);
  const auto failed = failed_starts_.find(id);
  if (failed != failed_starts_.end()) throw failed->second;
  if (it == episodes_.end()) {
    throw InvalidArgument("episode", "episode " + std::to_string(id) + " at step " + std::to_string(step) +
                                         " was never started (no EpisodeStart)");
  }
  Episode& episode = it->second;
  if (episode.round == round_) {
    throw InvalidArgument("duplicate", "episode " + std::to_string(id) + " has two scans in one batch");
  }
  episode.round = round_;
  const Cell position = toCell(batch.positions[i]);
  requireOnGrid(position, episode.width, episode.height, "position");
  const std::size_t count = static_cast<std::size_t>(2 * batch.range + 1) * (2 * batch.range + 1);
  const Scan view(batch.range, window, count, position, episode.goal, batch.bumped[i] != 0, static_cast<int>(step));
  return static_cast<std::uint8_t>(episode.agent->act(view));
}

void BatchResponder::start(const ppp_msgs::EpisodeStart& start) {
  host_.finish(start.episode);
  episodes_.erase(start.episode);
  const auto side_ok = [](std::uint32_t side) { return side >= kMinGridSide && side <= kMaxGridSide; };
  if (!side_ok(start.width) || !side_ok(start.height)) {
    throw InvalidArgument("size", "the map size " + std::to_string(start.width) + "x" +
                                      std::to_string(start.height) + " is outside [" +
                                      std::to_string(kMinGridSide) + ", " + std::to_string(kMaxGridSide) + "]");
  }
  EpisodeInfo info;
  info.width = static_cast<int>(start.width);
  info.height = static_cast<int>(start.height);
  info.start = toCell(start.start);
  info.goal = toCell(start.goal);
  info.seed = start.agent_seed;
  requireOnGrid(info.start, info.width, info.height, "start");
  requireOnGrid(info.goal, info.width, info.height, "goal");
  std::unique_ptr<Grid> prior;
  if (!start.prior_map.empty()) {
    const std::size_t cells = static_cast<std::size_t>(info.width) * static_cast<std::size_t>(info.height);
    if (start.prior_map.size() != cells) {
      throw InvalidArgument("prior_map", "expected " + std::to_string(cells) + " cells for a " +
                                             std::to_string(info.width) + "x" + std::to_string(info.height) +
                                             " map, got " + std::to_string(start.prior_map.size()));
    }
    prior = std::make_unique<Grid>(info.width, info.height);
    for (std::size_t i = 0; i < cells; ++i) {
      const std::int8_t value = start.prior_map[i];
      if (value != kScanFree && value != kScanObstacle) {
        throw InvalidArgument("prior_map", "cell " + std::to_string(i) + " is " + std::to_string(value) +
                                               "; expected FREE (0) or OBSTACLE (100)");
      }
      prior->setObstacle(prior->cellAt(static_cast<int>(i)), value == kScanObstacle);
    }
  }
  Agent& agent = host_.start(start.episode, info, prior.get());
  episodes_[start.episode] = Episode{info.width, info.height, info.goal, &agent, 0};
}

void BatchResponder::reject(std::uint32_t episode, std::uint32_t step, const std::string& kind,
                            const std::string& what) {
  // A duplicate scan leaves its episode alone: the first scan was answered.
  if (kind != "duplicate") {
    host_.finish(episode);
    episodes_.erase(episode);
  }
  if (rejections_[kind]++ == 0) {
    ROS_WARN("agent '%s': rejected the scan of episode %u step %u (%s); answered with action %d, which is no "
             "move. Further '%s' faults are not logged.",
             config_.name.c_str(), episode, step, what.c_str(), kRejectedAction, kind.c_str());
  }
}

}  // namespace agents
}  // namespace ppp
