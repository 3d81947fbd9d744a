// mrpt_planner_node: MRPT's wavefront planner for circular robots (mrpt::nav::PlannerSimple2D) on the robot's
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
// Topics are relative: start the node in the bridge's robot namespace (/G/robot).
#include <ros/ros.h>

#include "mrpt_grid_planner.hpp"
#include "planner_node.hpp"
#include "ppp_core/error.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "mrpt_planner");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    namespace planners = ppp::planners;
    planners::PlannerNodeOptions options;
    options.frames = planners::readPlannerFrames(private_nh, ros::this_node::getNamespace());
    options.unknown_is_free = planners::readMrptNodeParameters(private_nh).unknown_is_free;
    options.replan_on_map = true;
    // MRPT grows the obstacles itself: the map reaches it as the bridge sent it, the inflation as its radius.
    const double inflation = planners::readPlannerBody(private_nh).inflation;
    const planners::MrptGridPlanner planner(inflation);
    planners::PlannerNode node(nh, options, [&planner](const planners::GridMap& map, ppp::Cell robot, ppp::Cell goal) {
      try {
        return planner.plan(map, robot, goal);
      } catch (const ppp::Error& e) {
        ROS_WARN("no path: %s", e.what());
        return std::vector<ppp::MapPoint>{};
      }
    });
    ROS_INFO("MRPT planner (PlannerSimple2D, robot radius %.3f map cells, unknown cells %s, re-plans on every new "
             "map): %s",
             inflation, options.unknown_is_free ? "free" : "blocked", node.topics().c_str());
    node.run();
  } catch (const ppp::Error& e) {
    ROS_FATAL("%s", e.what());
    return 1;
  }
  return 0;
}
