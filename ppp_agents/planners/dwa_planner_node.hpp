#pragma once

// The DWA example: a dynamic-window local planner (dynamic_window.hpp) for a differential-drive robot, as ROS's
// dwa_local_planner works, answering each request with a velocity command (topics: velocity_planner_link.hpp):
//   publishes   cmd_vel (geometry_msgs/TwistStamped)  in continuous motion linear x and angular z (diff drive) or
//                                                     linear x and y (holonomic) in the robot's frame; on the
//                                                     grid linear x (east) and y (north)
//   parameters  ~kinematics, the robot's limits, ~robot_radius, the window's weights, ~map_frame, ~base_frame:
//               docs/reference/options.md#example-planner-nodes
// Obstacles are the scan's returns (NaN and out-of-range readings dropped, as a costmap drops them); the rollouts
// are scored by the cost of the route from their ends to the goal around every return seen this episode
// (scan_costmap.hpp, over the extent of the map the bridge publishes). It runs as a process of its own
// (dwa_planner_node) or as the nodelet ppp_agents/DwaPlanner.

#include <string>

#include "dwa_planner.hpp"
#include "planner_node_options.hpp"
#include "velocity_planner_link.hpp"

namespace ppp {
namespace planners {

/// Answers each request with DwaPlanner's choice.
class DwaPlannerNode {
 public:
  /// @throws InvalidArgument naming a bad parameter.
  DwaPlannerNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& node_name,
                 bool in_network_thread);

 private:
  /// The command for `request`.
  geometry_msgs::Twist command(const VelocityRequest& request);

  DwaNodeParameters parameters_;
  DwaPlanner planner_;
  VelocityPlannerLink link_;  // last: its callbacks use the members above
};

}  // namespace planners
}  // namespace ppp
