#include "planner_node_parameters.hpp"

#include "ppp_msgs/node_parameters.h"

namespace ppp {
namespace planners {

PlannerFrames readPlannerFrames(const ros::NodeHandle& private_nh, const std::string& node_namespace) {
  PlannerFrames frames;
  frames.base_frame = defaultBaseFrame(node_namespace);
  ppp_msgs::readOptionParameters(private_nh, plannerFrameSpecs(), &frames);
  ppp_msgs::validateParameters(frames);
  return frames;
}

PlannerBody readPlannerBody(const ros::NodeHandle& private_nh) {
  PlannerBody body;
  ppp_msgs::readOptionParameters(private_nh, plannerBodySpecs(), &body);
  ppp_msgs::validateParameters(body);
  return body;
}

OmplNodeParameters readOmplNodeParameters(const ros::NodeHandle& private_nh) {
  OmplNodeParameters parameters;
  ppp_msgs::readOptionParameters(private_nh, omplNodeOptionSpecs(), &parameters);
  ppp_msgs::validateParameters(parameters);
  return parameters;
}

}  // namespace planners
}  // namespace ppp
