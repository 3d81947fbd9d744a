#include "planner_bridge.hpp"

#include <array>

#include <boost/make_shared.hpp>

#include "planner_bridge_messages.hpp"
#include "ppp_agents/protocol/batch_codec.hpp"
#include "ppp_agents/protocol/batch_responder.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/sensor.hpp"
#include "ppp_core/window_mask.hpp"
#include "ppp_msgs/graph_names.h"

namespace ppp {
namespace agents {

PlannerBridge::PlannerBridge(ros::NodeHandle& nh, const BridgeParameters& parameters, bool in_network_thread)
    : parameters_(parameters), link_(nh, parameters, in_network_thread), scans_queue_(in_network_thread) {
  if (in_network_thread) worker_ = std::thread([this] { askPlanner(); });
}

PlannerBridge::~PlannerBridge() {
  link_.stop();
  scans_.shutdown();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  work_.notify_one();
  if (worker_.joinable()) worker_.join();
}

void PlannerBridge::serve(ros::NodeHandle& nh) {
  // The simulator sends its first scans once both topics are connected, so none come before the planner.
  moves_ = nh.advertise<ppp_msgs::MoveBatch>(ppp_msgs::topics::kMoves, 10);
  scans_ = ppp_msgs::subscribeLockstep<ppp_msgs::ScanBatch>(
      nh, ppp_msgs::topics::kScans, 10, [this](const ppp_msgs::ScanBatch::ConstPtr& b) { onScans(b); },
      scans_queue_.get());
}

void PlannerBridge::warnOnce(const std::string& kind, const std::string& text) {
  if (warnings_[kind]++ == 0) {
    ROS_WARN("bridge '%s': %s (further '%s' warnings are not logged)", parameters_.config.name.c_str(),
             text.c_str(), kind.c_str());
  }
}

void PlannerBridge::onScans(const ppp_msgs::ScanBatch::ConstPtr& batch) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (asking_ || !waiting_.empty()) {
    waiting_.push_back(batch);  // the worker is asking the planner: it plays this next, in order
    return;
  }
  play(batch);
}

void PlannerBridge::play(const ppp_msgs::ScanBatch::ConstPtr& batch) {
  const std::size_t n = batch->episodes.size();
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
      const std::optional<StepOutcome> outcome = step(*batch);
      if (!outcome && !worker_.joinable()) {  // a nodelet asks the planner here, in the scan's thread
        const StepOutcome answer = request();
        return reply(*batch, &answer);
      }
      if (!outcome) {  // a plan request: the worker waits for the answer and replies
        asking_ = batch;
        work_.notify_one();
        return;
      }
      return reply(*batch, &*outcome);
    }
  }
  reply(*batch, nullptr);
}

void PlannerBridge::reply(const ppp_msgs::ScanBatch& batch, const StepOutcome* outcome) {
  std::vector<protocol::MoveReply> replies(batch.episodes.size());
  for (std::size_t i = 0; i < replies.size(); ++i) {
    replies[i] = {batch.episodes[i], i < batch.steps.size() ? batch.steps[i] : 0, protocol::kRejectedAction};
  }
  if (outcome && !replies.empty()) {
    replies[0].action = outcome->action;
    replies[0].failure = outcome->failure;
    replies[0].diagnosis = outcome->diagnosis;
    // In lockstep the bridge's state decides the next move: its digest can prove a loop endless, when the planner
    // has no memory of its own.
    if (parameters_.lockstep && parameters_.endless_proof && outcome->failure == nullptr) {
      replies[0].state = episode_.stateDigest(following_);
    }
  }
  // A new message per batch, published by pointer: a simulator in the same manager gets this very object.
  auto moves = boost::make_shared<ppp_msgs::MoveBatch>(protocol::encodeMoves(parameters_.config.name, batch.batch,
                                                                              replies));
  moves->header.stamp = ros::Time::now();
  moves_.publish(moves);
}

void PlannerBridge::askPlanner() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    work_.wait(lock, [&] { return stopping_ || asking_ || !waiting_.empty(); });
    if (stopping_) return;
    if (!asking_) {  // a batch that came while the worker asked
      const ppp_msgs::ScanBatch::ConstPtr next = waiting_.front();
      waiting_.pop_front();
      play(next);  // may hand over a plan request: the next round asks
      continue;
    }
    const ppp_msgs::ScanBatch::ConstPtr batch = asking_;
    lock.unlock();  // the network thread goes on reading paths (and queueing scans) meanwhile
    const StepOutcome outcome = request();
    reply(*batch, &outcome);
    lock.lock();
    asking_ = nullptr;
  }
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
    episode_stamp_ = ros::Time();
    active_ = true;
  } catch (const InvalidArgument& e) {
    warnOnce(e.name(), "rejected the start of episode " + std::to_string(s.episode) + ": " + e.what());
  }
}

std::optional<PlannerBridge::StepOutcome> PlannerBridge::step(const ppp_msgs::ScanBatch& batch) {
  const std::uint32_t id = batch.episodes[0];
  const StepOutcome rejected{protocol::kRejectedAction, nullptr};
  if (!active_ || id != episode_id_) {
    warnOnce("episode", "episode " + std::to_string(id) + " was never started (no EpisodeStart)");
    return rejected;
  }
  Request& r = request_;
  r.robot = protocol::toCell(batch.positions[0]);
  r.range = batch.range;
  try {
    protocol::requireOnGrid(r.robot, episode_.frame().width, episode_.frame().height, "position");
    unpackWindow(batch.free_cells.data(), batch.obstacle_cells.data(), r.range, r.cells.data());
    episode_.observe(Scan(r.range, r.cells.data(), protocol::windowCells(r.range), r.robot, episode_.goal(),
                          batch.bumped[0] != 0, static_cast<int>(batch.steps[0])));
  } catch (const InvalidArgument& e) {
    warnOnce(e.name(), std::string("rejected a scan: ") + e.what());
    active_ = false;
    return rejected;
  }
  r.stamp = ros::Time::now();
  if (episode_stamp_.isZero()) episode_stamp_ = r.stamp;
  if (const std::optional<Action> along = episode_.moveWithoutRequest(parameters_)) {
    // Nothing to ask the planner (plan_requests): the robot goes on along its path; the planner gets the pose.
    link_.publishPose(r.stamp, episode_, r.robot, r.cells.data(), r.range);
    if (link_.gone()) return fail(reason::kPlannerLost, "the planner's process is gone");
    return StepOutcome{static_cast<std::uint8_t>(*along), nullptr};
  }
  link_.publishState(r.stamp, episode_stamp_, episode_, r.robot, r.cells.data(), r.range);
  if (link_.gone()) return fail(reason::kPlannerLost, "the planner's process is gone");
  if (!parameters_.lockstep) {
    // Free-running: a path the planner published on its own (re-planning on the new map) replaces the current
    // one if usable, whenever it arrives; without one the robot follows the path it has.
    std::vector<MapPoint> points;
    const std::optional<nav_msgs::Path> unasked = link_.takeUnasked();
    if (unasked && pathPoints(*unasked, parameters_.map_frame, &points).empty()) episode_.offer(points, r.robot);
    if (const std::optional<Action> action = episode_.next(r.robot)) {
      return StepOutcome{static_cast<std::uint8_t>(*action), nullptr};
    }
  }
  return std::nullopt;
}

PlannerBridge::StepOutcome PlannerBridge::request() {
  // Lockstep: this step is a request, and only the answer to this step's state moves the robot (a re-plan on
  // this step's map that arrived already is that answer).
  const Request& r = request_;
  link_.publishGoal(r.stamp, episode_);
  // Asked again as it was, with its own stamp: a planner that restarted gets it, and one that is only slow answers
  // it once (a second request for one state would change a planner with a memory of its own).
  const auto resend = [&] {
    link_.publishState(r.stamp, episode_stamp_, episode_, r.robot, r.cells.data(), r.range);
    link_.publishGoal(r.stamp, episode_);
  };
  const auto silent = [&](const char* what) {
    if (link_.lostWhileWaiting() || !link_.alive()) return fail(reason::kPlannerLost, "the planner's process is gone");
    return fail(reason::kPlannerTimeout,
                std::string("no ") + what + " within " + std::to_string(parameters_.plan_timeout) + " s");
  };
  if (commandsVelocity(parameters_)) {
    const std::optional<VelocityAnswer> answer = link_.waitForCommand(r.stamp, resend);
    if (!answer) return silent("velocity command");
    if (answer->aborted) return fail(reason::kPlannerAborted, "the planner gave up: " + *answer->aborted);
    return takeCommand(answer->command);
  }
  const std::optional<nav_msgs::Path> path =
      link_.waitForPath(r.stamp, [&](const nav_msgs::Path& p) { return answers(p, r.robot); }, resend);
  return path ? followPath(*path) : silent("path");
}

PlannerBridge::StepOutcome PlannerBridge::fail(const char* reason, const std::string& detail) {
  // Every reason is in results.csv: the log gets a sample, not a line per failed run of a long hunt.
  ROS_INFO_THROTTLE(5, "bridge '%s': episode %u fails as %s: %s", parameters_.config.name.c_str(), episode_id_,
                    reason, detail.c_str());
  active_ = false;
  return StepOutcome{0, reason};
}

}  // namespace agents
}  // namespace ppp
