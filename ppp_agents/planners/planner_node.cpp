#include "planner_node.hpp"

#include <nav_msgs/Path.h>

#include <boost/make_shared.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>

#include "ppp_core/error.hpp"
#include "ppp_msgs/graph_names.h"
#include "ppp_msgs/hand_over.h"

namespace ppp {
namespace planners {

namespace {

/// Odometry messages kept to find a request's pose by its stamp (a free-running bridge may be a few steps ahead).
constexpr std::size_t kPosesKept = 64;

}  // namespace

GridMap gridMapOf(const nav_msgs::OccupancyGrid& map, bool unknown_is_free, double inflation) {
  const geometry_msgs::Point& origin = map.info.origin.position;
  if (origin.x != 0.0 || origin.y != 0.0) {
    throw InvalidArgument("map.info.origin",
                          "expected (0, 0), got (" + std::to_string(origin.x) + ", " + std::to_string(origin.y) + ")");
  }
  return GridMap(static_cast<int>(map.info.width), static_cast<int>(map.info.height), map.info.resolution, map.data,
                 unknown_is_free, inflation);
}

PlannerNode::PlannerNode(ros::NodeHandle& nh, PlannerNodeOptions options, PlanFunction plan, bool in_network_thread)
    : options_(std::move(options)),
      plan_(std::move(plan)),
      plan_publisher_(nh.advertise<nav_msgs::Path>(ppp_msgs::topics::kPlannerPath, 1, true)),
      queue_(in_network_thread),
      map_subscriber_(ppp_msgs::subscribeLockstep<nav_msgs::OccupancyGrid>(
          nh, ppp_msgs::topics::kPlannerMap, 1, [this](const nav_msgs::OccupancyGrid::ConstPtr& m) { onMap(m); },
          queue_.get())),
      odom_subscriber_(ppp_msgs::subscribeLockstep<nav_msgs::Odometry>(
          nh, ppp_msgs::topics::kPlannerOdom, 1, [this](const nav_msgs::Odometry::ConstPtr& o) { onOdom(o); },
          queue_.get())),
      goal_subscriber_(ppp_msgs::subscribeLockstep<geometry_msgs::PoseStamped>(
          nh, ppp_msgs::topics::kPlannerGoal, 1, [this](const geometry_msgs::PoseStamped::ConstPtr& g) { onGoal(g); },
          queue_.get())),
      static_frames_subscriber_(nh.subscribe<tf2_msgs::TFMessage>(
          "/tf_static", 10, [this](const tf2_msgs::TFMessage::ConstPtr& t) { onStaticFrames(t); })) {}

std::string PlannerNode::topics() const {
  return map_subscriber_.getTopic() + ", " + goal_subscriber_.getTopic() + " -> " + plan_publisher_.getTopic() +
         "; pose: " + odom_subscriber_.getTopic() + " (" + options_.frames.map_frame + " -> " +
         options_.frames.base_frame + ")";
}

void PlannerNode::onMap(const nav_msgs::OccupancyGrid::ConstPtr& map) {
  std::lock_guard<std::mutex> lock(mutex_);
  map_ = map;
  serveReady();
}

void PlannerNode::onOdom(const nav_msgs::Odometry::ConstPtr& odom) {
  std::lock_guard<std::mutex> lock(mutex_);
  poses_.push_back(odom);
  if (poses_.size() > kPosesKept) poses_.pop_front();
  serveReady();
}

void PlannerNode::onGoal(const geometry_msgs::PoseStamped::ConstPtr& goal) {
  std::lock_guard<std::mutex> lock(mutex_);
  goal_ = goal;
  goal_pending_ = true;
  goal_reached_ = false;
  serveReady();
}

void PlannerNode::onStaticFrames(const tf2_msgs::TFMessage::ConstPtr& transforms) {
  for (const geometry_msgs::TransformStamped& t : transforms->transforms) {
    static_frames_.setTransform(t, "tf_static", true);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  serveReady();  // a goal may have waited for the frame of its pose
}

std::string PlannerNode::positionOf(const nav_msgs::Odometry& pose, MapPoint* position) const {
  const std::string& frame = pose.header.frame_id;
  if (pose.child_frame_id != options_.frames.base_frame) {
    return "odometry of frame '" + pose.child_frame_id + "', expected '" + options_.frames.base_frame + "'";
  }
  const geometry_msgs::Point& p = pose.pose.pose.position;
  if (frame == options_.frames.map_frame) {
    *position = MapPoint{p.x, p.y};
    return "";
  }
  // Continuous motion: odometry in the odom frame, which /tf_static places in the map.
  if (!static_frames_.canTransform(options_.frames.map_frame, frame, ros::Time(0))) {
    return "odometry in frame '" + frame + "', which is neither '" + options_.frames.map_frame +
           "' nor placed in it by /tf_static";
  }
  const geometry_msgs::TransformStamped t = static_frames_.lookupTransform(options_.frames.map_frame, frame, ros::Time(0));
  const geometry_msgs::Quaternion& q = t.transform.rotation;
  const double yaw = std::atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));
  *position = MapPoint{t.transform.translation.x + std::cos(yaw) * p.x - std::sin(yaw) * p.y,
                       t.transform.translation.y + std::sin(yaw) * p.x + std::cos(yaw) * p.y};
  return "";
}

nav_msgs::Odometry::ConstPtr PlannerNode::poseAt(const ros::Time& stamp) const {
  nav_msgs::Odometry::ConstPtr found;
  for (const nav_msgs::Odometry::ConstPtr& odom : poses_) {
    if (odom->header.stamp <= stamp) found = odom;  // the newest not newer than the stamp
  }
  return found;
}

bool PlannerNode::replanDue() const {
  // The bridge republishes the map every step; only a map that says something new is worth a new plan. A map of a
  // new episode (loaded after the goal was asked) waits for that episode's goal; an unstamped goal is always current.
  if (!options_.replan_on_map || !goal_ || goal_reached_ || !map_ || map_ == planned_map_) return false;
  const bool goal_of_this_map = goal_->header.stamp.isZero() || goal_->header.stamp >= map_->info.map_load_time;
  return goal_of_this_map && (!planned_map_ || map_->data != planned_map_->data);
}

void PlannerNode::serveReady() {
  Request request;
  request.goal = goal_;
  if (goal_pending_) {
    // The bridge publishes map and pose, then the goal, all with one stamp: the goal waits for them.
    request.pose_stamp = goal_->header.stamp;
    if (!map_ || map_->header.stamp < request.pose_stamp || !hasPoseAt(request.pose_stamp)) return;
    const nav_msgs::Odometry::ConstPtr pose = poseAt(request.pose_stamp);
    const std::string frame = pose ? pose->header.frame_id : options_.frames.map_frame;
    if (frame != options_.frames.map_frame &&
        !static_frames_.canTransform(options_.frames.map_frame, frame, ros::Time(0))) {
      ROS_WARN_THROTTLE(5, "the goal waits for /tf_static to place the odometry's frame '%s' in '%s'", frame.c_str(),
                        options_.frames.map_frame.c_str());
      return;
    }
    goal_pending_ = false;
  } else {
    if (!replanDue() || !hasPoseAt(map_->header.stamp)) return;
    request.replan = true;
    request.pose_stamp = map_->header.stamp;
  }
  request.map = map_;
  request.pose = poseAt(request.pose_stamp);  // never an older pose than the request's
  planned_map_ = map_;
  serve(request);
}

void PlannerNode::serve(const Request& request) {
  const geometry_msgs::PoseStamped& goal = *request.goal;
  if (!goal.header.frame_id.empty() && goal.header.frame_id != options_.frames.map_frame) {
    ROS_WARN("goal in frame '%s', expected '%s'; not planning", goal.header.frame_id.c_str(),
             options_.frames.map_frame.c_str());
    return;
  }
  if (!request.pose) {  // every pose kept is newer than the request's (a late goal)
    ROS_WARN("no robot pose (odometry) stamped %.3f or earlier; not planning", request.pose_stamp.toSec());
    return;
  }
  MapPoint position;
  const std::string pose_problem = positionOf(*request.pose, &position);
  if (!pose_problem.empty()) {
    ROS_WARN("%s; not planning", pose_problem.c_str());
    return;
  }
  try {
    const GridMap map = gridMapOf(*request.map, options_.unknown_is_free, options_.body.inflation);
    const Cell robot = map.cellOf(position);
    const Cell target = map.cellOf(MapPoint{goal.pose.position.x, goal.pose.position.y});
    if (!map.contains(target)) {
      ROS_WARN_THROTTLE(5, "the goal (%.3f, %.3f) lies off the map (%.3f x %.3f m): answering no path",
                        goal.pose.position.x, goal.pose.position.y, map.frame().width * map.frame().resolution,
                        map.frame().height * map.frame().resolution);
    }
    if (request.replan && robot == target) {
      goal_reached_ = true;
      return;
    }
    if (keepsLastPlan(request, map, robot, target)) {
      publish(last_plan_.waypoints, request.pose_stamp);
      return;
    }
    if (options_.episode_started && request.map->info.map_load_time != planned_episode_) options_.episode_started();
    planned_episode_ = request.map->info.map_load_time;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<MapPoint> waypoints = plan_(map, robot, target);
    last_plan_ = LastPlan{waypoints, robot, target, request.pose_stamp, request.map};
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char text[160];
    std::snprintf(text, sizeof text, "planned cell (%d, %d) -> (%d, %d)%s in %.6f s: %zu waypoints", robot.x, robot.y,
                  target.x, target.y, request.replan ? " on a new map" : "", seconds, waypoints.size());
    if (plan_time_logged_) {
      ROS_DEBUG("%s", text);
    } else {
      ROS_INFO("%s (further plan times at DEBUG level)", text);
      plan_time_logged_ = true;
    }
    // Stamped with the state it was planned for: the pose's stamp (the goal's, or the new map's for a
    // re-plan), so a late answer to an old request never looks like an answer to a newer one.
    publish(waypoints, request.pose_stamp);
  } catch (const Error& e) {
    ROS_WARN("not planning: %s", e.what());
  }
}

bool PlannerNode::keepsLastPlan(const Request& request, const GridMap& map, Cell robot, Cell target) const {
  const LastPlan& last = last_plan_;
  if (!last.map || last.target != target || last.waypoints.empty()) return false;
  if (request.pose_stamp == last.stamp) return true;  // the same state: a re-plan on its map answered it already
  // The robot moved on along the plan and the map says nothing new (a new run of the same PPP starts where the
  // plan did, and gets a new plan).
  if (robot == last.from || (last.map != request.map && last.map->data != request.map->data)) return false;
  return map.pathPasses(last.waypoints, robot);
}

void PlannerNode::publish(const std::vector<MapPoint>& waypoints, const ros::Time& stamp) {
  // A new message per plan, published by pointer: a bridge in the same manager gets this very object.
  auto path = boost::make_shared<nav_msgs::Path>();
  path->header.frame_id = options_.frames.map_frame;
  path->header.stamp = stamp;
  path->poses.resize(waypoints.size());
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    path->poses[i].header = path->header;
    path->poses[i].pose.position.x = waypoints[i].x;
    path->poses[i].pose.position.y = waypoints[i].y;
    path->poses[i].pose.orientation.w = 1.0;
  }
  ppp_msgs::publishHandingOver(plan_publisher_, path);
}

}  // namespace planners
}  // namespace ppp
