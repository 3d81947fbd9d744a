#include "mrpt_planner_node.hpp"

#include "planner_node_parameters.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace planners {

namespace {

PlannerNodeOptions mrptOptions(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh) {
  PlannerNodeOptions options;
  options.frames = readPlannerFrames(private_nh, nh.getNamespace());
  options.unknown_is_free = readMrptNodeParameters(private_nh).unknown_is_free;
  options.replan_on_map = true;
  return options;
}

}  // namespace

MrptPlannerNode::MrptPlannerNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh,
                                 const std::string& /*node_name*/, bool in_network_thread)
    : options_(mrptOptions(nh, private_nh)),
      inflation_(readPlannerBody(private_nh).inflation),
      planner_(inflation_),
      node_(nh, options_, [this](const GridMap& map, Cell robot, Cell goal) { return plan(map, robot, goal); },
            in_network_thread) {
  ROS_INFO("MRPT planner (PlannerSimple2D, robot radius %.3f map cells, unknown cells %s, re-plans on every new "
           "map): %s",
           inflation_, options_.unknown_is_free ? "free" : "blocked", node_.topics().c_str());
}

std::vector<MapPoint> MrptPlannerNode::plan(const GridMap& map, Cell robot, Cell goal) const {
  try {
    return planner_.plan(map, robot, goal);
  } catch (const Error& e) {
    ROS_WARN("no path: %s", e.what());
    return {};
  }
}

}  // namespace planners
}  // namespace ppp
