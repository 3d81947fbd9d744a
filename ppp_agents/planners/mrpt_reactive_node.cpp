#include "mrpt_reactive_node.hpp"

#include <boost/make_shared.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "planner_node.hpp"
#include "planner_node_parameters.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/motion_options.hpp"
#include "ppp_msgs/graph_names.h"
#include "ppp_msgs/hand_over.h"

namespace ppp {
namespace planners {
namespace {

/// Scans and poses kept to find a request's by its stamp.
constexpr std::size_t kKept = 16;

/// The newest message of `messages` stamped exactly `stamp`, or null.
template <class Message>
typename Message::ConstPtr stampedAt(const std::deque<typename Message::ConstPtr>& messages, const ros::Time& stamp) {
  for (auto it = messages.rbegin(); it != messages.rend(); ++it) {
    if ((*it)->header.stamp == stamp) return *it;
  }
  return nullptr;
}

/// Keeps `message` among the newest kKept of `messages`.
template <class Message>
void keep(std::deque<Message>* messages, Message message) {
  messages->push_back(std::move(message));
  if (messages->size() > kKept) messages->pop_front();
}

}  // namespace

ReactiveNode::ReactiveNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& /*node_name*/,
                           bool in_network_thread)
    : frames_(readPlannerFrames(private_nh, nh.getNamespace())),
      parameters_(readReactiveNodeParameters(private_nh)),
      navigator_(parameters_.method),
      queue_(in_network_thread) {
  namespace names = ppp_msgs::topics;
  command_ = nh.advertise<geometry_msgs::TwistStamped>(names::kPlannerCommand, 10);
  scan_ = ppp_msgs::subscribeLockstep<sensor_msgs::LaserScan>(
      nh, names::kPlannerScan, 10, [this](const sensor_msgs::LaserScan::ConstPtr& m) { onScan(m); }, queue_.get());
  odom_ = ppp_msgs::subscribeLockstep<nav_msgs::Odometry>(
      nh, names::kPlannerOdom, 10, [this](const nav_msgs::Odometry::ConstPtr& m) { onOdom(m); }, queue_.get());
  map_ = ppp_msgs::subscribeLockstep<nav_msgs::OccupancyGrid>(
      nh, names::kPlannerMap, 2, [this](const nav_msgs::OccupancyGrid::ConstPtr& m) { onMap(m); }, queue_.get());
  goal_ = ppp_msgs::subscribeLockstep<geometry_msgs::PoseStamped>(
      nh, names::kPlannerGoal, 10, [this](const geometry_msgs::PoseStamped::ConstPtr& m) { onGoal(m); },
      queue_.get());
  ROS_INFO("MRPT reactive navigator (%s, obstacles from the %s, range %s): %s", parameters_.method.c_str(),
           parameters_.obstacles.c_str(),
           parameters_.range > 0 ? (std::to_string(parameters_.range) + " m").c_str() : "the scan's range_max",
           topics().c_str());
}

std::string ReactiveNode::topics() const {
  return scan_.getTopic() + ", " + odom_.getTopic() + ", " + map_.getTopic() + ", " + goal_.getTopic() + " -> " +
         command_.getTopic();
}

void ReactiveNode::onScan(const sensor_msgs::LaserScan::ConstPtr& scan) {
  std::lock_guard<std::mutex> lock(mutex_);
  keep(&scans_, scan);
  continuous() ? drive() : serve();
}

void ReactiveNode::onOdom(const nav_msgs::Odometry::ConstPtr& odom) {
  std::lock_guard<std::mutex> lock(mutex_);
  keep(&poses_, odom);
  continuous() ? drive() : serve();
}

void ReactiveNode::onMap(const nav_msgs::OccupancyGrid::ConstPtr& map) {
  std::lock_guard<std::mutex> lock(mutex_);
  map_message_ = map;
  serve();
}

void ReactiveNode::onGoal(const geometry_msgs::PoseStamped::ConstPtr& goal) {
  if (goal->header.frame_id != frames_.map_frame) {
    ROS_WARN("a goal in frame '%s', expected '%s': not answered", goal->header.frame_id.c_str(),
             frames_.map_frame.c_str());
    return;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  pending_ = goal;
  if (continuous()) {
    goal_pose_ = goal;  // the episode's goal; the periods' scans and poses ask
    drive();
  } else {
    serve();
  }
}

void ReactiveNode::serve() {
  if (!pending_ || !map_message_ || map_message_->header.stamp < pending_->header.stamp) return;
  const ros::Time stamp = pending_->header.stamp;
  const sensor_msgs::LaserScan::ConstPtr scan = stampedAt<sensor_msgs::LaserScan>(scans_, stamp);
  const nav_msgs::Odometry::ConstPtr pose = stampedAt<nav_msgs::Odometry>(poses_, stamp);
  if (!scan || !pose) return;
  const geometry_msgs::PoseStamped goal = *pending_;
  pending_ = nullptr;
  if (pose->header.frame_id != frames_.map_frame || pose->child_frame_id != frames_.base_frame) {
    ROS_WARN("odometry of frame '%s' in frame '%s', expected '%s' in '%s': not answered", pose->child_frame_id.c_str(),
             pose->header.frame_id.c_str(), frames_.base_frame.c_str(), frames_.map_frame.c_str());
    return;
  }
  respond(stamp, *scan, *pose, goal);
}

void ReactiveNode::drive() {
  if (!goal_pose_ || !map_message_ || scans_.empty()) return;
  const ros::Time stamp = scans_.back()->header.stamp;
  if (stamp <= answered_) return;
  const nav_msgs::Odometry::ConstPtr pose = stampedAt<nav_msgs::Odometry>(poses_, stamp);
  if (!pose) return;
  answered_ = stamp;
  respond(stamp, *scans_.back(), *pose, *goal_pose_);
}

void ReactiveNode::respond(const ros::Time& stamp, const sensor_msgs::LaserScan& scan, const nav_msgs::Odometry& pose,
                           const geometry_msgs::PoseStamped& goal) {
  if (map_message_->info.map_load_time != episode_) {  // a new episode
    episode_ = map_message_->info.map_load_time;
    navigator_.reset();
  }
  // A new message per answer, published by pointer: a bridge in the same manager gets this very object.
  auto command = boost::make_shared<geometry_msgs::TwistStamped>();
  command->header.stamp = stamp;
  command->header.frame_id = frames_.base_frame;
  try {
    const Heading heading = steer(scan, pose, goal);
    const double speed = heading.speed * parameters_.max_speed;
    if (parameters_.kinematics == kKinematicsDiffDrive) {
      // Turn towards the direction, and drive as much of the speed as lies ahead.
      command->twist.linear.x = speed * std::max(0.0, std::cos(heading.direction));
      command->twist.angular.z = std::clamp(2 * heading.direction, -parameters_.max_turn, parameters_.max_turn);
    } else {  // the direction itself: east and north on the grid, the robot's frame when holonomic
      command->twist.linear.x = speed * std::cos(heading.direction);
      command->twist.linear.y = speed * std::sin(heading.direction);
    }
  } catch (const Error& e) {
    ROS_ERROR_THROTTLE(5, "the robot stays: %s", e.what());
  }
  ppp_msgs::publishHandingOver(command_, command);
}

Heading ReactiveNode::steer(const sensor_msgs::LaserScan& scan, const nav_msgs::Odometry& pose,
                            const geometry_msgs::PoseStamped& goal) {
  const double range = parameters_.range > 0 ? parameters_.range : scan.range_max;
  if (!(range > 0) || !std::isfinite(range)) {
    throw InvalidArgument("range", "the scan's range_max is " + std::to_string(scan.range_max) +
                                       ": set ~range to the metres obstacle distances are fractions of");
  }
  const MapPoint robot{pose.pose.pose.position.x, pose.pose.pose.position.y};
  std::vector<double> obstacles;
  if (parameters_.obstacles == kObstaclesFromMemory) {
    obstacles = sectorObstaclesInMap(gridMapOf(*map_message_, true, 0), robot, range);
  } else {
    if (!(std::isfinite(scan.angle_increment) && scan.angle_increment != 0) || !std::isfinite(scan.angle_min)) {
      throw InvalidArgument("scan", "angle_min " + std::to_string(scan.angle_min) + " and angle_increment " +
                                        std::to_string(scan.angle_increment) + " place no ray");
    }
    int invalid = 0;
    obstacles = sectorObstacles(LaserRays{scan.angle_min, scan.angle_increment, scan.ranges}, range, &invalid);
    if (invalid > 0) {
      ROS_WARN_THROTTLE(5, "scan at %.3f: %d of %zu rays are NaN (no reading), taken as obstacles at the robot",
                        scan.header.stamp.toSec(), invalid, scan.ranges.size());
    }
  }
  // The goal in the robot's frame, as the scan's directions are (on the grid the robot's frame is the map's).
  const double east = (goal.pose.position.x - robot.x) / range;
  const double north = (goal.pose.position.y - robot.y) / range;
  const auto& q = pose.pose.pose.orientation;
  const double heading = continuous() ? 2 * std::atan2(q.z, q.w) : 0.0;
  const MapPoint target{std::cos(heading) * east + std::sin(heading) * north,
                        -std::sin(heading) * east + std::cos(heading) * north};
  if (!std::isfinite(target.x) || !std::isfinite(target.y)) {
    throw InvalidArgument("goal", "a goal or pose that is not a finite point");
  }
  return navigator_.navigate(obstacles, target);
}

}  // namespace planners
}  // namespace ppp
