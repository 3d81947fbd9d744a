// ompl_planner_node: OMPL geometric planning on the robot's map (docs/reference/planner-interface.md).
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
// Topics are relative: start the node in the bridge's robot namespace (/G/robot).
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>
#include <ros/ros.h>

#include "ompl_grid_planner.hpp"
#include "planner_node.hpp"
#include "ppp_core/error.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "ompl_planner");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    namespace planners = ppp::planners;
    const planners::OmplNodeParameters parameters = planners::readOmplNodeParameters(private_nh);
    ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(parameters.planner.seed));  // OMPL's streams besides a plan's
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    planners::PlannerNodeOptions options;
    options.frames = planners::readPlannerFrames(private_nh, ros::this_node::getNamespace());
    options.body = planners::readPlannerBody(private_nh);
    options.unknown_is_free = parameters.unknown_is_free;
    const planners::OmplGridPlanner planner(parameters.planner);
    planners::PlannerNode node(nh, options, [&planner](const planners::GridMap& map, ppp::Cell robot, ppp::Cell goal) {
      return planner.plan(map, robot, goal);
    });
    ROS_INFO("OMPL planner %s (per plan: %d iterations, %.3f s of wall clock, 0: no limit; seed %d, unknown cells "
             "%s): %s",
             parameters.planner.planner.c_str(), parameters.planner.iterationLimit(),
             parameters.planner.planning_time, parameters.planner.seed, parameters.unknown_is_free ? "free" : "blocked",
             node.topics().c_str());
    node.run();
  } catch (const ppp::Error& e) {
    ROS_FATAL("%s", e.what());
    return 1;
  }
  return 0;
}
