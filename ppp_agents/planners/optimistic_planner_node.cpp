// optimistic_planner_node: repeated A* that treats unknown cells as free (docs/reference/planner-interface.md).
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
// Topics are relative: start the node in the bridge's robot namespace (/G/robot).
#include <ros/ros.h>

#include "optimistic_astar.hpp"
#include "planner_node.hpp"
#include "ppp_core/error.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "optimistic_planner");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    namespace planners = ppp::planners;
    planners::PlannerNodeOptions options;
    options.frames = planners::readPlannerFrames(private_nh, ros::this_node::getNamespace());
    options.body = planners::readPlannerBody(private_nh);
    options.unknown_is_free = true;
    options.replan_on_map = true;
    planners::PlannerNode node(nh, options, [](const planners::GridMap& map, ppp::Cell robot, ppp::Cell goal) {
      std::vector<ppp::MapPoint> centres;
      for (const ppp::Cell cell : planners::optimisticAStar(map, robot, goal)) centres.push_back(map.centre(cell));
      return centres;
    });
    ROS_INFO("optimistic planner (A*, unknown cells free, re-plans on every new map): %s", node.topics().c_str());
    node.run();
  } catch (const ppp::Error& e) {
    ROS_FATAL("%s", e.what());
    return 1;
  }
  return 0;
}
