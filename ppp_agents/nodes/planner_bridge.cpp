#include "planner_bridge.hpp"

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/master.h>
#include <sensor_msgs/LaserScan.h>

#include <algorithm>
#include <cmath>

#include "agent_node_parameters.hpp"
#include "batch_responder.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/sensor.hpp"
#include "ppp_msgs/conversions.h"
#include "ppp_msgs/node_liveness.h"
#include "ppp_msgs/node_parameters.h"
#include "scan_batch_checks.hpp"

namespace ppp {
namespace agents {

namespace {

constexpr double kProbePeriod = 0.2;  // seconds between asks whether the planner's process is alive

/// A frame name without a leading slash (tf2 frames have none).
std::string bareFrame(const std::string& frame) { return frame.empty() || frame[0] != '/' ? frame : frame.substr(1); }

/// The type the master has for `topic` ("" when nobody advertises it).
std::string advertisedType(const std::string& topic) {
  ros::master::V_TopicInfo topics;
  if (!ros::master::getTopics(topics)) return "";
  for (const ros::master::TopicInfo& t : topics) {
    if (t.name == topic) return t.datatype;
  }
  return "";
}

}  // namespace

BridgeParameters readBridgeParameters(const ros::NodeHandle& nh, const std::string& ns) {
  BridgeParameters p;
  p.config.type = kPlannerType;
  p.config.name = baseName(ns);
  readParameter(nh, "name", &p.config.name, "a string");
  if (p.config.name.empty()) {
    throw InvalidArgument("~name", "required when the bridge runs outside an agent's namespace (e.g. ns=\"ompl\")");
  }
  std::string memory = "full";
  readParameter(nh, "memory", &memory, "a string: KxK with odd K (e.g. 5x5) or 'full'");
  p.config.memory_window = parseMemoryWindow(memory, "~memory");
  readParameter(nh, "sensor_noise", &p.config.sensor_noise, "a number (a probability in [0, 1])");
  readParameter(nh, "resolution", &p.resolution, "a number of metres per cell");
  readParameter(nh, "plan_timeout", &p.plan_timeout, "a number of seconds");
  readParameter(nh, "connect_timeout", &p.connect_timeout, "a number of seconds");
  readParameter(nh, "map_frame", &p.map_frame, "a frame name");
  p.base_frame = bareFrame(ns == "/" ? "robot/base_link" : ns + "/robot/base_link");
  readParameter(nh, "base_frame", &p.base_frame, "a frame name");
  ppp_msgs::requirePositive(p.resolution, "~resolution");
  ppp_msgs::requirePositive(p.plan_timeout, "~plan_timeout");
  ppp_msgs::requirePositive(p.connect_timeout, "~connect_timeout");
  p.map_frame = bareFrame(p.map_frame);
  p.base_frame = bareFrame(p.base_frame);
  if (p.map_frame.empty()) throw InvalidArgument("~map_frame", "expected a non-empty frame name");
  if (p.base_frame.empty()) throw InvalidArgument("~base_frame", "expected a non-empty frame name");
  try {
    p.config.validate();
  } catch (const InvalidArgument& e) {
    throw InvalidArgument("~" + e.name(), std::string(e.what()).substr(e.name().size() + 2));
  }
  return p;
}

PlannerBridge::PlannerBridge(ros::NodeHandle& nh, const BridgeParameters& parameters)
    : parameters_(parameters), planner_nh_(nh, "robot"), plan_spinner_(1, &plan_queue_) {
  moves_ = nh.advertise<ppp_msgs::MoveBatch>("moves", 10);
  map_ = planner_nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
  odom_ = planner_nh_.advertise<nav_msgs::Odometry>("odom", 10);
  scan_ = planner_nh_.advertise<sensor_msgs::LaserScan>("scan", 10);
  goal_ = planner_nh_.advertise<geometry_msgs::PoseStamped>("move_base_simple/goal", 10);
  ros::SubscribeOptions options = ros::SubscribeOptions::create<nav_msgs::Path>(
      "plan", 10, [this](const nav_msgs::Path::ConstPtr& path) { onPlan(path); }, ros::VoidPtr(), &plan_queue_);
  options.transport_hints = ros::TransportHints().tcpNoDelay();  // Nagle would hold each path back 40 ms
  plan_ = planner_nh_.subscribe(options);
  plan_spinner_.start();
  scans_ = nh.subscribe("scans", 10, &PlannerBridge::onScans, this, ros::TransportHints().tcpNoDelay());
}

PlannerBridge::~PlannerBridge() { plan_spinner_.stop(); }

std::string PlannerBridge::plannerTopics() const {
  return map_.getTopic() + ", " + odom_.getTopic() + ", " + scan_.getTopic() + ", " + goal_.getTopic() + " -> " +
         plan_.getTopic() + "; tf " + parameters_.map_frame + " -> " + parameters_.base_frame;
}

void PlannerBridge::waitForPlanner() {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(parameters_.connect_timeout);
  std::string wrong_type;
  for (int poll = 0; ros::ok(); ++poll) {
    if (goal_.getNumSubscribers() > 0 && plannerConnected()) return;
    if (poll % 10 == 0) {
      const std::string type = advertisedType(plan_.getTopic());
      if (!type.empty() && type != "nav_msgs/Path") {
        wrong_type = plan_.getTopic() + " is published as " + type + "; expected nav_msgs/Path";
        break;
      }
    }
    if (ros::WallTime::now() >= deadline) break;
    ros::WallDuration(0.05).sleep();  // polling connection counts: there is no event to wait on
  }
  if (!ros::ok()) return;
  std::string missing = wrong_type;
  const auto add = [&missing](const std::string& text) { missing += (missing.empty() ? "" : "; ") + text; };
  if (wrong_type.empty() && !plannerConnected()) add("nothing publishes " + plan_.getTopic() + " (nav_msgs/Path)");
  if (goal_.getNumSubscribers() == 0) {
    add("nothing subscribes to " + goal_.getTopic() +
        " (geometry_msgs/PoseStamped; a subscriber of another type cannot connect)");
  }
  throw InvalidArgument("planner", missing + ". Start the planner in namespace " + planner_nh_.getNamespace() +
                                       " or remap its topics to these names (docs/planner-interface.md)");
}

void PlannerBridge::onPlan(const nav_msgs::Path::ConstPtr& path) {
  std::lock_guard<std::mutex> lock(path_mutex_);
  latest_path_ = *path;
  ++paths_received_;
  path_arrived_.notify_one();
}

bool PlannerBridge::plannerGone() {
  if (!planner_answered_) return false;
  if (!plannerConnected()) return true;
  // A killed process leaves its link retrying and its registration in place: ask it, a few times a second.
  const ros::WallTime now = ros::WallTime::now();
  if (now < next_probe_) return false;
  next_probe_ = now + ros::WallDuration(kProbePeriod);
  return !ppp_msgs::publisherAlive(plan_.getTopic());
}

void PlannerBridge::warnOnce(const std::string& kind, const std::string& text) {
  if (warnings_[kind]++ == 0) {
    ROS_WARN("bridge '%s': %s (further '%s' warnings are not logged)", parameters_.config.name.c_str(),
             text.c_str(), kind.c_str());
  }
}

void PlannerBridge::onScans(const ppp_msgs::ScanBatch::ConstPtr& batch) {
  const std::size_t n = batch->episodes.size();
  ppp_msgs::MoveBatch moves;
  moves.agent = parameters_.config.name;
  moves.batch = batch->batch;
  moves.episodes = batch->episodes;
  moves.steps = batch->steps;
  moves.steps.resize(n);
  moves.actions.assign(n, kRejectedAction);
  std::string what;
  const std::string fault = checkBatchShape(*batch, true, &what);
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
      if (outcome.failure.empty()) {
        moves.actions[0] = outcome.action;
      } else {
        ppp_msgs::EpisodeFailure failure;
        failure.episode = batch->episodes[0];
        failure.reason = outcome.failure;
        moves.failures.push_back(failure);
      }
    }
  }
  moves.header.stamp = ros::Time::now();
  moves_.publish(moves);
}

void PlannerBridge::start(const ppp_msgs::EpisodeStart& s) {
  active_ = false;
  try {
    const ParsedStart parsed = parseEpisodeStart(s);
    episode_id_ = s.episode;
    episode_.start(parsed.info, parsed.prior.get(), parameters_.config.memory_window, parameters_.resolution);
    planner_answered_ = false;
    std::lock_guard<std::mutex> lock(path_mutex_);
    paths_used_ = paths_received_;  // a path sent for an earlier episode is not this one's
    active_ = true;
  } catch (const InvalidArgument& e) {
    warnOnce(e.name(), "rejected the start of episode " + std::to_string(s.episode) + ": " + e.what());
  }
}

PlannerBridge::StepOutcome PlannerBridge::step(const ppp_msgs::ScanBatch& batch) {
  const std::uint32_t id = batch.episodes[0];
  const StepOutcome rejected{kRejectedAction, ""};
  if (!active_ || id != episode_id_) {
    warnOnce("episode", "episode " + std::to_string(id) + " was never started (no EpisodeStart)");
    return rejected;
  }
  const Cell robot = toCell(batch.positions[0]);
  const int range = batch.range;
  const std::size_t count = static_cast<std::size_t>(2 * range + 1) * (2 * range + 1);
  try {
    requireOnGrid(robot, episode_.frame().width, episode_.frame().height, "position");
    episode_.observe(Scan(range, batch.cells.data(), count, robot, episode_.goal(), batch.bumped[0] != 0,
                          static_cast<int>(batch.steps[0])));
  } catch (const InvalidArgument& e) {
    warnOnce(e.name(), std::string("rejected a scan: ") + e.what());
    active_ = false;
    return rejected;
  }
  const auto fail = [&](const std::string& reason, const std::string& detail) {
    ROS_INFO("bridge '%s': episode %u fails as %s: %s", parameters_.config.name.c_str(), id, reason.c_str(),
             detail.c_str());
    active_ = false;
    return StepOutcome{0, reason};
  };
  const ros::Time stamp = ros::Time::now();
  publishState(stamp, robot, batch.cells.data(), range);
  if (plannerGone()) return fail(ppp_msgs::EpisodeFailure::PLANNER_LOST, "the planner's process is gone");

  // A path the planner published on its own (re-planning on the new map) replaces the current one if usable.
  std::optional<nav_msgs::Path> unasked;
  {
    std::lock_guard<std::mutex> lock(path_mutex_);
    if (paths_received_ > paths_used_) unasked = latest_path_;
    paths_used_ = paths_received_;
  }
  std::vector<MapPoint> points;
  if (unasked && pathPoints(*unasked, &points).empty()) episode_.offer(points, robot);
  std::optional<Action> action = episode_.next(robot);
  if (!action) {
    publishGoal(stamp);
    const std::optional<nav_msgs::Path> path = waitForPath(stamp, robot, batch.cells.data(), range);
    if (!path) {
      if (!plannerConnected() || !ppp_msgs::publisherAlive(plan_.getTopic())) {
        return fail(ppp_msgs::EpisodeFailure::PLANNER_LOST, "the planner's process is gone");
      }
      return fail(ppp_msgs::EpisodeFailure::PLANNER_TIMEOUT,
                  "no path within " + std::to_string(parameters_.plan_timeout) + " s");
    }
    planner_answered_ = true;
    const std::string frame_problem = pathPoints(*path, &points);
    if (!frame_problem.empty()) return fail(ppp_msgs::EpisodeFailure::INVALID_PATH, frame_problem);
    const Answer answer = episode_.answer(points, robot);
    if (answer.verdict == AnswerVerdict::NoPath) return fail(ppp_msgs::EpisodeFailure::NO_PATH, answer.detail);
    if (answer.verdict == AnswerVerdict::InvalidPath) {
      return fail(ppp_msgs::EpisodeFailure::INVALID_PATH, answer.detail);
    }
    action = answer.action;
  }
  return StepOutcome{static_cast<std::uint8_t>(*action), ""};
}

std::optional<nav_msgs::Path> PlannerBridge::waitForPath(ros::Time stamp, Cell robot, const std::int8_t* window,
                                                         int range) {
  const ros::Time request = stamp;
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(parameters_.plan_timeout);
  ros::WallTime resend = ros::WallTime::now() + ros::WallDuration(1.0);
  std::optional<nav_msgs::Path> unusable;  // the last path that does not fit the request
  std::unique_lock<std::mutex> lock(path_mutex_);
  while (ros::ok()) {
    if (paths_received_ > paths_used_) {
      paths_used_ = paths_received_;
      // A path stamped before the request answers an earlier one (stamp 0 means "now"). One that does not fit
      // (not from the robot's cell, not to the goal, through a known wall) may still be a late answer to an
      // earlier request carrying a newer map's stamp: wait for another, and judge it if none comes.
      const nav_msgs::Path& path = *latest_path_;
      if (path.header.stamp.isZero() || path.header.stamp >= request) {
        if (answers(path, robot)) return path;
        unusable = path;
      }
    }
    // A planner that answered in this episode and is gone now died mid-episode: no point waiting.
    if (plannerGone()) break;
    const ros::WallTime now = ros::WallTime::now();
    if (now >= deadline) break;
    if (now >= resend) {
      // A planner that (re)started since the request missed it: send the state and the goal again.
      lock.unlock();
      stamp = ros::Time::now();
      publishState(stamp, robot, window, range);
      publishGoal(stamp);
      lock.lock();
      resend = now + ros::WallDuration(1.0);
      continue;
    }
    // Wake at least every 50 ms to see whether the planner is still connected (no event says it left).
    const ros::WallTime until = std::min({deadline, resend, now + ros::WallDuration(0.05)});
    path_arrived_.wait_for(lock, std::chrono::nanoseconds((until - now).toNSec()));
  }
  return unusable;
}

bool PlannerBridge::answers(const nav_msgs::Path& path, Cell robot) const {
  std::vector<MapPoint> points;
  // A path in a wrong frame is an answer, and a wrong one: judged by the caller.
  return !pathPoints(path, &points).empty() || episode_.fits(points, robot);
}

std::string PlannerBridge::pathPoints(const nav_msgs::Path& path, std::vector<MapPoint>* points) const {
  points->clear();
  if (bareFrame(path.header.frame_id) != parameters_.map_frame) {
    return "the path is in frame '" + path.header.frame_id + "'; expected '" + parameters_.map_frame + "'";
  }
  for (const geometry_msgs::PoseStamped& pose : path.poses) {
    const std::string frame = bareFrame(pose.header.frame_id);
    if (!frame.empty() && frame != parameters_.map_frame) {
      return "a pose of the path is in frame '" + pose.header.frame_id + "'; expected '" + parameters_.map_frame +
             "'";
    }
    if (!std::isfinite(pose.pose.position.x) || !std::isfinite(pose.pose.position.y)) {
      return "a pose of the path is not a finite point";
    }
    points->push_back(MapPoint{pose.pose.position.x, pose.pose.position.y});
  }
  return "";
}

void PlannerBridge::publishState(const ros::Time& stamp, Cell robot, const std::int8_t* window, int range) {
  const MapFrame& frame = episode_.frame();
  nav_msgs::OccupancyGrid map;
  map.header.stamp = stamp;
  map.header.frame_id = parameters_.map_frame;
  map.info.map_load_time = stamp;
  map.info.resolution = static_cast<float>(parameters_.resolution);
  map.info.width = static_cast<std::uint32_t>(frame.width);
  map.info.height = static_cast<std::uint32_t>(frame.height);
  map.info.origin.orientation.w = 1.0;
  map.data.resize(episode_.known().cells.size());
  // kScan* values are the OccupancyGrid's own: -1 unknown, 0 free, 100 obstacle.
  for (int y = 0; y < frame.height; ++y) {
    for (int x = 0; x < frame.width; ++x) map.data[frame.mapIndex(Cell{x, y})] = episode_.known().at(Cell{x, y});
  }
  map_.publish(map);

  geometry_msgs::TransformStamped transform;
  transform.header.stamp = stamp;
  transform.header.frame_id = parameters_.map_frame;
  transform.child_frame_id = parameters_.base_frame;
  transform.transform.translation.x = frame.centreX(robot);
  transform.transform.translation.y = frame.centreY(robot);
  transform.transform.rotation.w = 1.0;
  tf_.sendTransform(transform);

  nav_msgs::Odometry odom;
  odom.header = transform.header;
  odom.child_frame_id = parameters_.base_frame;
  odom.pose.pose.position.x = transform.transform.translation.x;
  odom.pose.pose.position.y = transform.transform.translation.y;
  odom.pose.pose.orientation.w = 1.0;
  odom_.publish(odom);

  sensor_msgs::LaserScan laser = ppp_msgs::toLaserScan(window, range, parameters_.resolution, parameters_.base_frame);
  laser.header.stamp = stamp;
  scan_.publish(laser);
}

void PlannerBridge::publishGoal(const ros::Time& stamp) {
  geometry_msgs::PoseStamped goal;
  goal.header.stamp = stamp;
  goal.header.frame_id = parameters_.map_frame;
  goal.pose.position.x = episode_.frame().centreX(episode_.goal());
  goal.pose.position.y = episode_.frame().centreY(episode_.goal());
  goal.pose.orientation.w = 1.0;
  goal_.publish(goal);
}

}  // namespace agents
}  // namespace ppp
