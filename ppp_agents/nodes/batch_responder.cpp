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

BatchResponder::BatchResponder(const AgentConfig& config) : config_(config), host_(config) {}

ppp_msgs::MoveBatch BatchResponder::answer(const ppp_msgs::ScanBatch& batch) {
  ++round_;
  ppp_msgs::MoveBatch moves;
  moves.agent = config_.name;
  moves.batch = batch.batch;
  moves.moves.resize(batch.scans.size());
  for (std::size_t i = 0; i < batch.scans.size(); ++i) {
    const ppp_msgs::EpisodeScan& scan = batch.scans[i];
    ppp_msgs::EpisodeMove& move = moves.moves[i];
    move.episode = scan.episode;
    move.step = scan.step;
    try {
      move.action = act(scan);
    } catch (const InvalidArgument& e) {
      reject(scan, e.name(), e.what());
      move.action = kRejectedAction;
    } catch (const std::exception& e) {
      reject(scan, "agent", e.what());
      move.action = kRejectedAction;
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

std::uint8_t BatchResponder::act(const ppp_msgs::EpisodeScan& scan) {
  auto it = episodes_.find(scan.episode);
  if (it != episodes_.end() && it->second.round == round_) {
    throw InvalidArgument("duplicate", "episode " + std::to_string(scan.episode) + " has two scans in one batch");
  }
  if (scan.step == 0) {
    start(scan);
    it = episodes_.find(scan.episode);
  }
  if (it == episodes_.end()) {
    throw InvalidArgument("episode", "episode " + std::to_string(scan.episode) + " at step " +
                                         std::to_string(scan.step) + " was never started (no step-0 scan)");
  }
  it->second.round = round_;
  const Cell position = toCell(scan.position);
  const Cell goal = toCell(scan.goal);
  requireOnGrid(position, it->second.width, it->second.height, "position");
  requireOnGrid(goal, it->second.width, it->second.height, "goal");
  const Scan view(scan.range, scan.cells, position, goal, scan.bumped, static_cast<int>(scan.step));
  return static_cast<std::uint8_t>(host_.act(scan.episode, view));
}

void BatchResponder::start(const ppp_msgs::EpisodeScan& scan) {
  host_.finish(scan.episode);
  episodes_.erase(scan.episode);
  const auto side_ok = [](std::uint32_t side) { return side >= kMinGridSide && side <= kMaxGridSide; };
  if (!side_ok(scan.width) || !side_ok(scan.height)) {
    throw InvalidArgument("size", "the map size " + std::to_string(scan.width) + "x" + std::to_string(scan.height) +
                                      " is outside [" + std::to_string(kMinGridSide) + ", " +
                                      std::to_string(kMaxGridSide) + "]");
  }
  EpisodeInfo info;
  info.width = static_cast<int>(scan.width);
  info.height = static_cast<int>(scan.height);
  info.start = toCell(scan.start);
  info.goal = toCell(scan.goal);
  info.seed = scan.agent_seed;
  requireOnGrid(info.start, info.width, info.height, "start");
  requireOnGrid(info.goal, info.width, info.height, "goal");
  std::unique_ptr<Grid> prior;
  if (!scan.prior_map.empty()) {
    const std::size_t cells = static_cast<std::size_t>(info.width) * static_cast<std::size_t>(info.height);
    if (scan.prior_map.size() != cells) {
      throw InvalidArgument("prior_map", "expected " + std::to_string(cells) + " cells for a " +
                                             std::to_string(info.width) + "x" + std::to_string(info.height) +
                                             " map, got " + std::to_string(scan.prior_map.size()));
    }
    prior = std::make_unique<Grid>(info.width, info.height);
    for (std::size_t i = 0; i < cells; ++i) {
      const std::int8_t value = scan.prior_map[i];
      if (value != kScanFree && value != kScanObstacle) {
        throw InvalidArgument("prior_map", "cell " + std::to_string(i) + " is " + std::to_string(value) +
                                               "; expected FREE (0) or OBSTACLE (100)");
      }
      prior->setObstacle(prior->cellAt(static_cast<int>(i)), value == kScanObstacle);
    }
  }
  host_.start(scan.episode, info, prior.get());
  episodes_[scan.episode] = Episode{info.width, info.height, 0};
}

void BatchResponder::reject(const ppp_msgs::EpisodeScan& scan, const std::string& kind, const std::string& what) {
  // A duplicate scan leaves its episode alone: the first scan was answered.
  if (kind != "duplicate") {
    host_.finish(scan.episode);
    episodes_.erase(scan.episode);
  }
  if (rejections_[kind]++ == 0) {
    ROS_WARN("agent '%s': rejected the scan of episode %u step %u (%s); answered with action %d, which is no "
             "move. Further '%s' faults are not logged.",
             config_.name.c_str(), scan.episode, scan.step, what.c_str(), kRejectedAction, kind.c_str());
  }
}

}  // namespace agents
}  // namespace ppp
