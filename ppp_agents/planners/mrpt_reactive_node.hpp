#pragma once

// The MRPT reactive example: a local planner on MRPT's holonomic reactive navigators (ND, VFF, FullEval), answering each
// plan request with a velocity command (docs/reference/planner-interface.md, "Velocity commands").
//   subscribes  scan (sensor_msgs/LaserScan)                the robot's scan, in its frame (aligned with the map's)
//               odom (nav_msgs/Odometry)                   the robot's pose (frame ~map_frame, child ~base_frame)
//               map (nav_msgs/OccupancyGrid)               what the robot knows; a new map_load_time starts a new
//                                                          episode (a new method object: ND remembers its last choice)
//               move_base_simple/goal (geometry_msgs/PoseStamped)  a request, answered once the scan, pose and map
//                                                          of its stamp are in
//   publishes   cmd_vel (geometry_msgs/TwistStamped)       the method's direction and speed (times ~max_speed) as
//                                                          linear x (east) and y (north), stamped with the goal's stamp;
//                                                          in continuous motion (~kinematics set) one command per
//                                                          control period, stamped with its scan's, in the robot's frame
//   parameters  ~method, ~obstacles, ~range, ~max_speed, ~map_frame, ~base_frame:
//               docs/reference/options.md#example-planner-nodes
// Topics are relative: start the node in the bridge's robot namespace (/G/robot). It runs as a process of its own
// (mrpt_reactive_node) or as the nodelet ppp_agents/MrptReactive.

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>

#include <deque>
#include <mutex>
#include <string>

#include "mrpt_reactive_navigator.hpp"
#include "planner_node_options.hpp"
#include "ppp_msgs/lockstep_queue.h"

namespace ppp {
namespace planners {

/// Answers each plan request with the navigator's velocity command, in the callback that completes its inputs.
class ReactiveNode {
 public:
  /// @throws InvalidArgument naming a bad parameter.
  ReactiveNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& node_name,
               bool in_network_thread);

 private:
  void onScan(const sensor_msgs::LaserScan::ConstPtr& scan);
  void onOdom(const nav_msgs::Odometry::ConstPtr& odom);
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& map);
  void onGoal(const geometry_msgs::PoseStamped::ConstPtr& goal);
  /// Answers the pending goal once the scan, pose and map of its step are in (mutex_ held).
  void serve();
  /// Continuous motion: answers each control period once its scan and pose are in (mutex_ held).
  void drive();
  /// True in continuous motion (~kinematics set): the robot has a heading, and the periods ask, not goals.
  bool continuous() const { return !parameters_.kinematics.empty(); }
  /// Publishes the command for the robot at `pose` seeing `scan`, bound for `goal`, stamped `stamp` (mutex_ held).
  void respond(const ros::Time& stamp, const sensor_msgs::LaserScan& scan, const nav_msgs::Odometry& pose,
               const geometry_msgs::PoseStamped& goal);
  /// The method's choice for the robot at `pose` heading for `goal`.
  Heading steer(const sensor_msgs::LaserScan& scan, const nav_msgs::Odometry& pose,
                const geometry_msgs::PoseStamped& goal);
  std::string topics() const;

  PlannerFrames frames_;
  ReactiveNodeParameters parameters_;
  MrptReactiveNavigator navigator_;
  std::mutex mutex_;  // held by each callback: a nodelet's may run in two threads (a publisher's and its own)
  std::deque<sensor_msgs::LaserScan::ConstPtr> scans_;
  std::deque<nav_msgs::Odometry::ConstPtr> poses_;
  nav_msgs::OccupancyGrid::ConstPtr map_message_;
  geometry_msgs::PoseStamped::ConstPtr pending_;  // the goal not answered yet
  geometry_msgs::PoseStamped::ConstPtr goal_pose_;  // continuous motion: the episode's goal
  ros::Time answered_;                              // continuous motion: the last period answered
  ros::Time episode_;                             // the map_load_time of the episode being played
  ros::Publisher command_;
  ppp_msgs::LockstepQueue queue_;  // before the subscriptions: they unsubscribe first
  ros::Subscriber scan_, odom_, map_, goal_;
};

}  // namespace planners
}  // namespace ppp
