// mrpt_reactive_node: a local planner on MRPT's holonomic reactive navigators (ND, VFF, FullEval), answering each
// plan request with a velocity command (docs/reference/planner-interface.md, "Velocity commands").
//   subscribes  scan (sensor_msgs/LaserScan)                the robot's scan, in its frame (aligned with the map's)
//               odom (nav_msgs/Odometry)                   the robot's pose (frame ~map_frame, child ~base_frame)
//               map (nav_msgs/OccupancyGrid)               what the robot knows; a new map_load_time starts a new
//                                                          episode (a new method object: ND remembers its last choice)
//               move_base_simple/goal (geometry_msgs/PoseStamped)  a request, answered once the scan, pose and map
//                                                          of its stamp are in
//   publishes   cmd_vel (geometry_msgs/TwistStamped)       the method's direction and speed (times ~max_speed) as
//                                                          linear x (east) and y (north), stamped with the goal's stamp
//   parameters  ~method, ~obstacles, ~range, ~max_speed, ~map_frame, ~base_frame:
//               docs/reference/options.md#example-planner-nodes
// Topics are relative: start the node in the bridge's robot namespace (/G/robot).
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>

#include <cmath>
#include <deque>
#include <string>
#include <utility>
#include <vector>

#include "mrpt_reactive_navigator.hpp"
#include "planner_node.hpp"
#include "planner_node_parameters.hpp"
#include "ppp_core/error.hpp"
#include "ppp_msgs/graph_names.h"

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

class ReactiveNode {
 public:
  ReactiveNode(ros::NodeHandle& nh, PlannerFrames frames, ReactiveNodeParameters parameters)
      : frames_(std::move(frames)), parameters_(std::move(parameters)), navigator_(parameters_.method) {
    namespace topics = ppp_msgs::topics;
    command_ = nh.advertise<geometry_msgs::TwistStamped>(topics::kPlannerCommand, 10);
    const ros::TransportHints nodelay = ros::TransportHints().tcpNoDelay();
    scan_ = nh.subscribe(topics::kPlannerScan, 10, &ReactiveNode::onScan, this, nodelay);
    odom_ = nh.subscribe(topics::kPlannerOdom, 10, &ReactiveNode::onOdom, this, nodelay);
    map_ = nh.subscribe(topics::kPlannerMap, 2, &ReactiveNode::onMap, this, nodelay);
    goal_ = nh.subscribe(topics::kPlannerGoal, 10, &ReactiveNode::onGoal, this, nodelay);
  }

  std::string topics() const {
    return scan_.getTopic() + ", " + odom_.getTopic() + ", " + map_.getTopic() + ", " + goal_.getTopic() + " -> " +
           command_.getTopic();
  }

 private:
  void onScan(const sensor_msgs::LaserScan::ConstPtr& scan) {
    keep(&scans_, scan);
    serve();
  }
  void onOdom(const nav_msgs::Odometry::ConstPtr& odom) {
    keep(&poses_, odom);
    serve();
  }
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& map) {
    map_message_ = map;
    serve();
  }
  void onGoal(const geometry_msgs::PoseStamped::ConstPtr& goal) {
    if (goal->header.frame_id != frames_.map_frame) {
      ROS_WARN("a goal in frame '%s', expected '%s': not answered", goal->header.frame_id.c_str(),
               frames_.map_frame.c_str());
      return;
    }
    pending_ = goal;
    serve();
  }

  /// Answers the pending goal once the scan, pose and map of its step are in.
  void serve() {
    if (!pending_ || !map_message_ || map_message_->header.stamp < pending_->header.stamp) return;
    const ros::Time stamp = pending_->header.stamp;
    const sensor_msgs::LaserScan::ConstPtr scan = stampedAt<sensor_msgs::LaserScan>(scans_, stamp);
    const nav_msgs::Odometry::ConstPtr pose = stampedAt<nav_msgs::Odometry>(poses_, stamp);
    if (!scan || !pose) return;
    const geometry_msgs::PoseStamped goal = *pending_;
    pending_ = nullptr;
    if (pose->header.frame_id != frames_.map_frame || pose->child_frame_id != frames_.base_frame) {
      ROS_WARN("odometry of frame '%s' in frame '%s', expected '%s' in '%s': not answered",
               pose->child_frame_id.c_str(), pose->header.frame_id.c_str(), frames_.base_frame.c_str(),
               frames_.map_frame.c_str());
      return;
    }
    if (map_message_->info.map_load_time != episode_) {  // a new episode
      episode_ = map_message_->info.map_load_time;
      navigator_.reset();
    }
    geometry_msgs::TwistStamped command;
    command.header.stamp = stamp;
    command.header.frame_id = frames_.base_frame;
    try {
      const Heading heading = steer(*scan, *pose, goal);
      command.twist.linear.x = heading.speed * parameters_.max_speed * std::cos(heading.direction);
      command.twist.linear.y = heading.speed * parameters_.max_speed * std::sin(heading.direction);
    } catch (const Error& e) {
      ROS_ERROR_THROTTLE(5, "the robot stays: %s", e.what());
    }
    command_.publish(command);
  }

  /// The method's choice for the robot at `pose` heading for `goal`.
  Heading steer(const sensor_msgs::LaserScan& scan, const nav_msgs::Odometry& pose,
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
    const MapPoint target{(goal.pose.position.x - robot.x) / range, (goal.pose.position.y - robot.y) / range};
    if (!std::isfinite(target.x) || !std::isfinite(target.y)) {
      throw InvalidArgument("goal", "a goal or pose that is not a finite point");
    }
    return navigator_.navigate(obstacles, target);
  }

  PlannerFrames frames_;
  ReactiveNodeParameters parameters_;
  MrptReactiveNavigator navigator_;
  ros::Publisher command_;
  ros::Subscriber scan_, odom_, map_, goal_;
  std::deque<sensor_msgs::LaserScan::ConstPtr> scans_;
  std::deque<nav_msgs::Odometry::ConstPtr> poses_;
  nav_msgs::OccupancyGrid::ConstPtr map_message_;
  geometry_msgs::PoseStamped::ConstPtr pending_;  // the goal not answered yet
  ros::Time episode_;                             // the map_load_time of the episode being played
};

}  // namespace
}  // namespace planners
}  // namespace ppp

int main(int argc, char** argv) {
  ros::init(argc, argv, "mrpt_reactive");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    namespace planners = ppp::planners;
    const planners::PlannerFrames frames = planners::readPlannerFrames(private_nh, ros::this_node::getNamespace());
    const planners::ReactiveNodeParameters parameters = planners::readReactiveNodeParameters(private_nh);
    planners::ReactiveNode node(nh, frames, parameters);
    ROS_INFO("MRPT reactive navigator (%s, obstacles from the %s, range %s): %s", parameters.method.c_str(),
             parameters.obstacles.c_str(),
             parameters.range > 0 ? (std::to_string(parameters.range) + " m").c_str() : "the scan's range_max",
             node.topics().c_str());
    ros::spin();
  } catch (const ppp::Error& e) {
    ROS_FATAL("%s", e.what());
    return 1;
  }
  return 0;
}
