#include "planner_node_parameters.hpp"

#include <utility>

#include "ppp_msgs/node_parameters.h"

namespace ppp {
namespace planners {

namespace {

/// `parameters` with every declared `~` parameter that is set read over it, then validated.
template <class Parameters>
Parameters readDeclared(const ros::NodeHandle& private_nh, const std::vector<OptionSpec<Parameters>>& specs,
                        Parameters parameters = {}) {
  ppp_msgs::readOptionParameters(private_nh, specs, &parameters);
  ppp_msgs::validateParameters(parameters);
  return parameters;
}

}  // namespace

PlannerFrames readPlannerFrames(const ros::NodeHandle& private_nh, const std::string& node_namespace) {
  PlannerFrames frames;
  frames.base_frame = defaultBaseFrame(node_namespace);
  return readDeclared(private_nh, plannerFrameSpecs(), std::move(frames));
}

PlannerBody readPlannerBody(const ros::NodeHandle& private_nh) {
  return readDeclared(private_nh, plannerBodySpecs());
}

PlannerPeriod readPlannerPeriod(const ros::NodeHandle& private_nh) {
  return readDeclared(private_nh, plannerPeriodSpecs());
}

OmplNodeParameters readOmplNodeParameters(const ros::NodeHandle& private_nh) {
  return readDeclared(private_nh, omplNodeOptionSpecs());
}

MrptNodeParameters readMrptNodeParameters(const ros::NodeHandle& private_nh) {
  return readDeclared(private_nh, mrptNodeOptionSpecs());
}

ReactiveNodeParameters readReactiveNodeParameters(const ros::NodeHandle& private_nh) {
  return readDeclared(private_nh, reactiveNodeOptionSpecs());
}

DwaNodeParameters readDwaNodeParameters(const ros::NodeHandle& private_nh) {
  return readDeclared(private_nh, dwaNodeOptionSpecs());
}

TpSpaceNodeParameters readTpSpaceNodeParameters(const ros::NodeHandle& private_nh) {
  return readDeclared(private_nh, tpSpaceNodeOptionSpecs());
}

ZooNodeParameters readZooNodeParameters(const ros::NodeHandle& private_nh) {
  return readDeclared(private_nh, zooNodeOptionSpecs());
}

}  // namespace planners
}  // namespace ppp
