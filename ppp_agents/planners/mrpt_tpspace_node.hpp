#pragma once

// The TP-space example: MRPT's reactive navigator for differential-drive robots (mrpt::nav::CReactiveNavigationSystem:
// trajectories of its PTGs, a holonomic method in TP-space, a motion decider), a local planner in continuous motion
// answering each control period with a velocity command (topics: velocity_planner_link.hpp):
//   publishes   cmd_vel (geometry_msgs/TwistStamped)  linear x and angular z, as the navigator's PTG drives
//   parameters  ~config, ~kinematics, ~max_linear_speed, ~max_angular_speed, ~robot_radius,
//               ~target_allowed_distance, ~map_frame, ~base_frame: docs/reference/options.md#example-planner-nodes
// It runs as a process of its own only (mrpt_tpspace_node): MRPT's clock, set to the robot's simulated time, is
// the process's.

#include <string>

#include "mrpt_tpspace_navigator.hpp"
#include "planner_node_options.hpp"
#include "velocity_planner_link.hpp"

namespace ppp {
namespace planners {

/// Answers each control period with the navigator's command.
class TpSpaceNode {
 public:
  /// @throws InvalidArgument naming a bad parameter, or the configuration file MRPT refuses.
  TpSpaceNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& node_name,
              bool in_network_thread);

 private:
  /// The command for `request`.
  geometry_msgs::Twist command(const VelocityRequest& request);

  TpSpaceNodeParameters parameters_;
  std::string config_path_;
  MrptTpSpaceNavigator navigator_;
  ros::Time episode_start_;  // the stamp of the episode's first period
  VelocityPlannerLink link_;  // last: its callbacks use the members above
};

}  // namespace planners
}  // namespace ppp
