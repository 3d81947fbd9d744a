#include "zoo_planner_node.hpp"

#include <memory>

#include "planted_faults.hpp"
#include "planner_node_parameters.hpp"

namespace ppp {
namespace planners {

namespace {

PlannerNodeOptions zooOptions(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh,
                              const std::shared_ptr<FaultyPlanner>& planner) {
  PlannerNodeOptions options;
  options.episode_started = [planner] { planner->startEpisode(); };
  options.frames = readPlannerFrames(private_nh, nh.getNamespace());
  options.unknown_is_free = true;
  options.replan_on_map = true;
  return options;
}

PlanFunction zooPlan(const std::shared_ptr<FaultyPlanner>& planner) {
  return [planner](const GridMap& map, Cell robot, Cell goal) {
    std::vector<MapPoint> centres;
    for (const Cell cell : planner->plan(map, robot, goal)) centres.push_back(map.centre(cell));
    return centres;
  };
}

std::shared_ptr<FaultyPlanner> faultyPlanner(const ros::NodeHandle& private_nh) {
  const ZooNodeParameters parameters = readZooNodeParameters(private_nh);
  return std::make_shared<FaultyPlanner>(parameters.fault, parameters.limit);
}

}  // namespace

ZooPlannerNode::ZooPlannerNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh,
                               const std::string& /*node_name*/, bool in_network_thread)
    : ZooPlannerNode(nh, private_nh, faultyPlanner(private_nh), in_network_thread) {}

ZooPlannerNode::ZooPlannerNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh,
                               const std::shared_ptr<FaultyPlanner>& planner, bool in_network_thread)
    : node_(nh, zooOptions(nh, private_nh, planner), zooPlan(planner), in_network_thread) {
  ROS_INFO("zoo planner (the optimistic planner with a planted fault): %s", node_.topics().c_str());
}

}  // namespace planners
}  // namespace ppp
