#pragma once

// The OMPL example planner: OMPL geometric planning on the robot's map (docs/reference/planner-interface.md).
//   subscribes  map (nav_msgs/OccupancyGrid)               what the robot knows: -1 unknown, 0 free, 100 obstacle
//               move_base_simple/goal (geometry_msgs/PoseStamped)  a plan request
//               odom (nav_msgs/Odometry)                   the robot's pose (frame ~map_frame, child ~base_frame),
//                                                          kept by stamp (the node reads no tf)
//   publishes   plan (nav_msgs/Path, latched)              simplified waypoints from the robot's cell centre to the
//                                                          goal's, every segment walking only passable cells;
//                                                          stamped with the pose's stamp (the goal's, or the map's);
//                                                          empty when OMPL finds no path within its limits.
//                                                          One per goal.
//   parameters  ~planner (RRTConnect, RRTstar or PRM), ~planning_iterations, ~planning_time, ~seed (each plan's
//               ompl::RNG seed derives from it), ~unknown_is_free, ~inflation, ~map_frame, ~base_frame (default:
//               the node's namespace + "/base_link", e.g. "ompl/robot/base_link" in /ompl/robot); their defaults
//               and ranges: docs/reference/options.md#example-planner-nodes
// Topics are relative: start the node in the bridge's robot namespace (/G/robot). It runs as a process of its own
// (ompl_planner_node) or as the nodelet ppp_agents/OmplPlanner.

#include <ros/ros.h>

#include <string>

#include "ompl_grid_planner.hpp"
#include "planner_node.hpp"

namespace ppp {
namespace planners {

class OmplPlannerNode {
 public:
  /// @throws InvalidArgument naming a bad parameter.
  OmplPlannerNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& node_name,
                  bool in_network_thread);

 private:
  OmplNodeParameters parameters_;
  OmplGridPlanner planner_;
  PlannerNode node_;
};

}  // namespace planners
}  // namespace ppp
