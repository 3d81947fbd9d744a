#pragma once

// The optimistic example planner: repeated A* that treats unknown cells as free (docs/reference/planner-interface.md).
//   subscribes  map (nav_msgs/OccupancyGrid)               what the robot knows: -1 unknown, 0 free, 100 obstacle
//               move_base_simple/goal (geometry_msgs/PoseStamped)  a plan request
//               odom (nav_msgs/Odometry)                   the robot's pose (frame ~map_frame, child ~base_frame),
//                                                          kept by stamp (the node reads no tf)
//   publishes   plan (nav_msgs/Path, latched)              the centre of every cell from the robot's to the goal's,
//                                                          stamped with the pose's stamp (the goal's, or the map's);
//                                                          empty when the map shows no path. Planned on every goal
//                                                          and again on every new map until the robot is on the goal.
//   parameters  ~inflation, ~map_frame, ~base_frame (default: the node's namespace + "/base_link", e.g.
//               "optimistic/robot/base_link" in /optimistic/robot): docs/reference/options.md#example-planner-nodes
// Topics are relative: start the node in the bridge's robot namespace (/G/robot). It runs as a process of its own
// (optimistic_planner_node) or as the nodelet ppp_agents/OptimisticPlanner.

#include <ros/ros.h>

#include <string>

#include "planner_node.hpp"

namespace ppp {
namespace planners {

class OptimisticPlannerNode {
 public:
  /// @throws InvalidArgument naming a bad parameter.
  OptimisticPlannerNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& node_name,
                        bool in_network_thread);

 private:
  PlannerNode node_;
};

}  // namespace planners
}  // namespace ppp
