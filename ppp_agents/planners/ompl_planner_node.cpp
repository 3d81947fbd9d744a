#include "ompl_planner_node.hpp"

#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "planner_node_parameters.hpp"

namespace ppp {
namespace planners {

namespace {

PlannerNodeOptions omplOptions(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh,
                               const OmplNodeParameters& parameters) {
  PlannerNodeOptions options;
  options.frames = readPlannerFrames(private_nh, nh.getNamespace());
  options.body = readPlannerBody(private_nh);
  options.unknown_is_free = parameters.unknown_is_free;
  return options;
}

/// The node's parameters. Each plan seeds its own stream from ~seed and the request; OMPL's process-wide streams
/// besides a plan's are seeded here, before anything plans, once per process: by a process of its own, never by a
/// nodelet (a manager may hold several, and OMPL refuses a second seed).
OmplNodeParameters seededParameters(const ros::NodeHandle& private_nh, bool own_process) {
  const OmplNodeParameters parameters = readOmplNodeParameters(private_nh);
  if (own_process) ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(parameters.planner.seed));
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  return parameters;
}

}  // namespace

OmplPlannerNode::OmplPlannerNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh,
                                 const std::string& /*node_name*/, bool in_network_thread)
    : parameters_(seededParameters(private_nh, in_network_thread)),
      planner_(parameters_.planner),
      node_(nh, omplOptions(nh, private_nh, parameters_),
            [this](const GridMap& map, Cell robot, Cell goal) { return planner_.plan(map, robot, goal); },
            in_network_thread) {
  ROS_INFO("OMPL planner %s (per plan: %d iterations, %.3f s of wall clock, 0: no limit; seed %d, unknown cells %s): "
           "%s",
           parameters_.planner.planner.c_str(), parameters_.planner.iterationLimit(), parameters_.planner.planning_time,
           parameters_.planner.seed, parameters_.unknown_is_free ? "free" : "blocked", node_.topics().c_str());
}

}  // namespace planners
}  // namespace ppp
