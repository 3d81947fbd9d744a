#include "planner_bridge.hpp"

#include <algorithm>
#include <array>

#include "planner_bridge_messages.hpp"
#include "ppp_agents/protocol/batch_codec.hpp"
#include "ppp_agents/protocol/batch_responder.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/sensor.hpp"
#include "ppp_core/window_mask.hpp"
#include "ppp_msgs/graph_names.h"

namespace ppp {
namespace agents {

namespace {

/// True when two paths have the same poses.
bool samePoints(const std::vector<MapPoint>& a, const std::vector<MapPoint>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const MapPoint& p, const MapPoint& q) { return p.x == q.x && p.y == q.y; });
}

}  // namespace

PlannerBridge::PlannerBridge(ros::NodeHandle& nh, const BridgeParameters& parameters)
    : parameters_(parameters), link_(nh, parameters) {
  moves_ = nh.advertise<ppp_msgs::MoveBatch>(ppp_msgs::topics::kMoves, 10);
  scans_ = nh.subscribe(ppp_msgs::topics::kScans, 10, &PlannerBridge::onScans, this, ros::TransportHints().tcpNoDelay());
}

void PlannerBridge::warnOnce(const std::string& kind, const std::string& text) {
  if (warnings_[kind]++ == 0) {
    ROS_WARN("bridge '%s': %s (further '%s' warnings are not logged)", parameters_.config.name.c_str(),
             text.c_str(), kind.c_str());
  }
}

void PlannerBridge::onScans(const ppp_msgs::ScanBatch::ConstPtr& batch) {
  const std::size_t n = batch->episodes.size();
  std::vector<protocol::MoveReply> replies(n);
  for (std::size_t i = 0; i < n; ++i) {
    replies[i] = {batch->episodes[i], i < batch->steps.size() ? batch->steps[i] : 0, protocol::kRejectedAction};
  }
  std::string what;
  const std::string fault = protocol::checkScanBatch(*batch, true, &what);
  if (!fault.empty()) {
    warnOnce(fault, "rejected a malformed batch: " + what);
  } else {
    for (const ppp_msgs::EpisodeStart& s : batch->starts) start(s);
    for (std::size_t i = 1; i < n; ++i) {
      warnOnce("batch_size", "the bridge plays one episode at a time; rejected the scan of episode " +
                                 std::to_string(batch->episodes[i]) + " (give the agent type planner)");
    }
    if (n > 0) {
      const StepOutcome outcome = step(*batch);
      replies[0].action = outcome.action;
      replies[0].failure = outcome.failure;
    }
  }
  ppp_msgs::MoveBatch moves = protocol::encodeMoves(parameters_.config.name, batch->batch, replies);
  moves.header.stamp = ros::Time::now();
  moves_.publish(moves);
}

void PlannerBridge::start(const ppp_msgs::EpisodeStart& s) {
  active_ = false;
  try {
    const protocol::EpisodeStart decoded = protocol::decodeEpisodeStart(s);
    const std::unique_ptr<Grid> prior = protocol::priorGrid(decoded);
    episode_id_ = s.episode;
    episode_.start(protocol::episodeInfo(decoded, nullptr), prior.get(), parameters_.config.memory_window,
                   parameters_.resolution);
    link_.newEpisode();
    following_.clear();
    previous_ = Cell{-1, -1};
    active_ = true;
  } catch (const InvalidArgument& e) {
    warnOnce(e.name(), "rejected the start of episode " + std::to_string(s.episode) + ": " + e.what());
  }
}

PlannerBridge::StepOutcome PlannerBridge::step(const ppp_msgs::ScanBatch& batch) {
  const std::uint32_t id = batch.episodes[0];
  const StepOutcome rejected{protocol::kRejectedAction, nullptr};
  if (!active_ || id != episode_id_) {
    warnOnce("episode", "episode " + std::to_string(id) + " was never started (no EpisodeStart)");
    return rejected;
  }
  const Cell robot = protocol::toCell(batch.positions[0]);
  const int range = batch.range;
  std::array<std::int8_t, kMaxScanCells> cells;  // the window, which the planner's LaserScan shows too
  bool map_changed = false;
  try {
    protocol::requireOnGrid(robot, episode_.frame().width, episode_.frame().height, "position");
    unpackWindow(batch.free_cells.data(), batch.obstacle_cells.data(), range, cells.data());
    map_changed = episode_.observe(Scan(range, cells.data(), protocol::windowCells(range), robot, episode_.goal(),
                                        batch.bumped[0] != 0, static_cast<int>(batch.steps[0])));
  } catch (const InvalidArgument& e) {
    warnOnce(e.name(), std::string("rejected a scan: ") + e.what());
    active_ = false;
    return rejected;
  }
  const auto fail = [&](const char* reason, const std::string& detail) {
    // Every reason is in results.csv: the log gets a sample, not a line per failed run of a long hunt.
    ROS_INFO_THROTTLE(5, "bridge '%s': episode %u fails as %s: %s", parameters_.config.name.c_str(), id, reason,
                      detail.c_str());
    active_ = false;
    return StepOutcome{0, reason};
  };
  const ros::Time stamp = ros::Time::now();
  const bool moved = robot != previous_;
  previous_ = robot;
  if (parameters_.lockstep && !asksEveryStep(parameters_) && moved && !(map_changed && asksOnChange(parameters_))) {
    // The robot moved on along the plan, and the map did not change (or changes are not asked about): it goes on
    // without a request (docs/planner-interface.md, "plan_requests").
    if (const std::optional<Action> along = episode_.next(robot)) {
      link_.publishPose(stamp, episode_, robot, cells.data(), range);
      if (link_.gone()) return fail(reason::kPlannerLost, "the planner's process is gone");
      return StepOutcome{static_cast<std::uint8_t>(*along), nullptr};
    }
  }
  link_.publishState(stamp, episode_, robot, cells.data(), range);
  if (link_.gone()) return fail(reason::kPlannerLost, "the planner's process is gone");

  std::vector<MapPoint> points;
  std::optional<Action> action;
  if (!parameters_.lockstep) {
    // Free-running: a path the planner published on its own (re-planning on the new map) replaces the current
    // one if usable, whenever it arrives; without one the robot follows the path it has.
    const std::optional<nav_msgs::Path> unasked = link_.takeUnasked();
    if (unasked && pathPoints(*unasked, parameters_.map_frame, &points).empty()) episode_.offer(points, robot);
    action = episode_.next(robot);
  }
  // Lockstep: this step is a request, and only the answer to this step's state moves the robot (a re-plan on
  // this step's map that arrived already is that answer).
  if (!action) {
    link_.publishGoal(stamp, episode_);
    const std::optional<nav_msgs::Path> path = link_.waitForPath(
        stamp, [&](const nav_msgs::Path& p) { return answers(p, robot); },
        [&](const ros::Time& again) {
          link_.publishState(again, episode_, robot, cells.data(), range);
          link_.publishGoal(again, episode_);
        });
    if (!path) {
      if (!link_.alive()) return fail(reason::kPlannerLost, "the planner's process is gone");
      return fail(reason::kPlannerTimeout,
                  "no path within " + std::to_string(parameters_.plan_timeout) + " s");
    }
    const std::string frame_problem = pathPoints(*path, parameters_.map_frame, &points);
    if (!frame_problem.empty()) return fail(reason::kInvalidPath, frame_problem);
    // The plan kept (the poses of the path being followed, sent again): the robot goes on from where it is along
    // it, rather than from the first place the path passes its cell (a path may pass a cell twice).
    if (!points.empty() && samePoints(points, following_)) action = episode_.next(robot);
    if (!action) {
      const Answer answer = episode_.answer(points, robot);
      if (answer.verdict == AnswerVerdict::NoPath) return fail(reason::kNoPath, answer.detail);
      if (answer.verdict == AnswerVerdict::InvalidPath) {
        return fail(reason::kInvalidPath, answer.detail);
      }
      following_ = points;
      action = answer.action;
    }
  }
  return StepOutcome{static_cast<std::uint8_t>(*action), nullptr};
}

bool PlannerBridge::answers(const nav_msgs::Path& path, Cell robot) const {
  std::vector<MapPoint> points;
  // A path in a wrong frame is an answer, and a wrong one: judged by the caller.
  return !pathPoints(path, parameters_.map_frame, &points).empty() || episode_.fits(points, robot);
}

}  // namespace agents
}  // namespace ppp
