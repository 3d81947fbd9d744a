#pragma once

// The MRPT reactive example: a local planner on MRPT's holonomic reactive navigators (ND, VFF, FullEval), answering each
// plan request with a velocity command (topics: velocity_planner_link.hpp):
//   publishes   cmd_vel (geometry_msgs/TwistStamped)       the method's direction and speed (times ~max_speed): on
//                                                          the grid as linear x (east) and y (north); in continuous
//                                                          motion (~kinematics set) in the robot's frame, a diff-drive
//                                                          robot turning towards the direction
//   parameters  ~method, ~obstacles, ~frame, ~range, ~max_speed, ~max_turn, ~robot_radius, ~kinematics, ~map_frame,
//               ~base_frame:
//               docs/reference/options.md#example-planner-nodes
// Its steering is ReactiveSteering (ROS-free). It runs as a process of its own (mrpt_reactive_node) or as the nodelet
// ppp_agents/MrptReactive.

#include <string>

#include "planner_node_options.hpp"
#include "reactive_steering.hpp"
#include "velocity_planner_link.hpp"

namespace ppp {
namespace planners {

/// Answers each request with the navigator's velocity command.
class ReactiveNode {
 public:
  /// @throws InvalidArgument naming a bad parameter.
  ReactiveNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& node_name,
               bool in_network_thread);

 private:
  /// True in continuous motion (~kinematics set): the robot has a heading.
  bool continuous() const { return !parameters_.kinematics.empty(); }
  /// The command for `request`.
  geometry_msgs::Twist command(const VelocityRequest& request);

  ReactiveNodeParameters parameters_;
  ReactiveSteering steering_;
  VelocityPlannerLink link_;  // last: its callbacks use the members above
};

}  // namespace planners
}  // namespace ppp
