#include "optimistic_planner_node.hpp"

#include "optimistic_astar.hpp"
#include "planner_node_parameters.hpp"

namespace ppp {
namespace planners {

namespace {

PlannerNodeOptions optimisticOptions(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh) {
  PlannerNodeOptions options;
  options.frames = readPlannerFrames(private_nh, nh.getNamespace());
  options.body = readPlannerBody(private_nh);
  options.unknown_is_free = true;
  options.replan_on_map = true;
  return options;
}

std::vector<MapPoint> optimisticPlan(const GridMap& map, Cell robot, Cell goal) {
  std::vector<MapPoint> centres;
  for (const Cell cell : optimisticAStar(map, robot, goal)) centres.push_back(map.centre(cell));
  return centres;
}

}  // namespace

OptimisticPlannerNode::OptimisticPlannerNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh,
                                             const std::string& /*node_name*/, bool in_network_thread)
    : node_(nh, optimisticOptions(nh, private_nh), optimisticPlan, in_network_thread) {
  ROS_INFO("optimistic planner (A*, unknown cells free, re-plans on every new map): %s", node_.topics().c_str());
}

}  // namespace planners
}  // namespace ppp
