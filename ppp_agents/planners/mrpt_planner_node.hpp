#pragma once

// The MRPT example planner: MRPT's wavefront planner for circular robots (mrpt::nav::PlannerSimple2D) on the robot's
// map (docs/reference/planner-interface.md).
//   subscribes  map (nav_msgs/OccupancyGrid)               what the robot knows: -1 unknown, 0 free, 100 obstacle
//               move_base_simple/goal (geometry_msgs/PoseStamped)  a plan request
//               odom (nav_msgs/Odometry)                   the robot's pose (frame ~map_frame, child ~base_frame),
//                                                          kept by stamp (the node reads no tf)
//   publishes   plan (nav_msgs/Path, latched)              the robot's cell centre, then MRPT's path (cell centres
//                                                          at least 0.4 m apart, MRPT's default) to the goal's;
//                                                          stamped with the pose's stamp (the goal's, or the map's);
//                                                          empty when MRPT finds no path. Planned on every goal and
//                                                          again on every new map until the robot is on the goal.
//   parameters  ~inflation (MRPT's robotRadius, in map cells), ~unknown_is_free, ~map_frame, ~base_frame (default:
//               the node's namespace + "/base_link"): docs/reference/options.md#example-planner-nodes
// Topics are relative: start the node in the bridge's robot namespace (/G/robot). It runs as a process of its own
// (mrpt_planner_node) or as the nodelet ppp_agents/MrptPlanner.

#include <ros/ros.h>

#include <string>

#include "mrpt_grid_planner.hpp"
#include "planner_node.hpp"

namespace ppp {
namespace planners {

class MrptPlannerNode {
 public:
  /// @throws InvalidArgument naming a bad parameter.
  MrptPlannerNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& node_name,
                  bool in_network_thread);

 private:
  std::vector<MapPoint> plan(const GridMap& map, Cell robot, Cell goal) const;

  PlannerNodeOptions options_;
  double inflation_;  // MRPT grows the obstacles itself: the map reaches it as the bridge sent it
  MrptGridPlanner planner_;
  PlannerNode node_;
};

}  // namespace planners
}  // namespace ppp
