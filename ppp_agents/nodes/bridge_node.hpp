#pragma once

// The planner bridge node: plays an agent of type planner with an external ROS planner, one episode at a time
// (docs/reference/planner-interface.md). Start it in the agent's namespace (ns="NAME"), the planner in NAME/robot.
//   simulator side  subscribes scans (ppp_msgs/ScanBatch)   publishes moves (ppp_msgs/MoveBatch); in continuous
//                   motion (interface cmd_vel) sensing (ppp_msgs/SensingBatch) and commands (ppp_msgs/CommandBatch)
//   planner side    publishes robot/map (nav_msgs/OccupancyGrid, latched), robot/odom (nav_msgs/Odometry),
//                   robot/scan (sensor_msgs/LaserScan), robot/move_base_simple/goal (geometry_msgs/PoseStamped)
//                   and tf map_frame -> base_frame; subscribes robot/plan (nav_msgs/Path); in continuous motion also
//                   robot/clock (rosgraph_msgs/Clock) and tf map -> odom -> base_link, and takes robot/cmd_vel
//   parameters      ~name (default: the namespace's last component), ~memory, ~sensor_noise (the simulator
//                   applies it) and the bridge's own (~plan_timeout, ~lockstep, ~connect_timeout, ~map_frame, ...):
//                   docs/reference/options.md#planner-bridge-node
// It runs as a process of its own (planner_bridge_node), which exits with an error naming the topics when no planner
// connects within ~connect_timeout (default 20 s; the experiment's graph gives a planner the user starts by hand
// 300 s), or as the nodelet ppp_agents/PlannerBridge, which then logs the error and serves nothing.

#include <ros/ros.h>

#include <string>
#include <thread>

#include "continuous_planner_bridge.hpp"
#include "planner_bridge.hpp"
#include "planner_bridge_parameters.hpp"

namespace ppp {
namespace agents {

/// Waits for the planner, then serves the simulator (PlannerBridge): in the constructor for a process of its own
/// (`in_network_thread`), in a thread of its own for a nodelet, which must not hold up its manager.
class BridgeNode {
 public:
  /// @throws InvalidArgument naming a bad parameter, or (a process of its own) the planner's missing topics.
  BridgeNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& node_name,
             bool in_network_thread);
  /// Stops waiting for the planner.
  ~BridgeNode();

 private:
  /// Waits for the planner, then subscribes to the simulator's scans. @throws InvalidArgument.
  void connect();

  ros::NodeHandle nh_;
  BridgeParameters parameters_;
  PlannerBridge bridge_;
  ContinuousPlannerBridge continuous_;  // the same planner in continuous motion
  std::thread connecting_;  // a nodelet's
};

}  // namespace agents
}  // namespace ppp
