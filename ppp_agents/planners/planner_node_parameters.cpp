#include "planner_node_parameters.hpp"

#include "ppp_core/error.hpp"
#include "ppp_msgs/node_parameters.h"

namespace ppp {
namespace planners {

namespace {

using ppp_msgs::readParameter;

void readFrame(const ros::NodeHandle& nh, const std::string& name, std::string* frame) {
  const std::string expected = "a tf frame name without a leading slash";
  readParameter(nh, name, frame, expected);
  if (frame->empty() || frame->front() == '/') {
    throw InvalidArgument("~" + name, "expected " + expected + ", got '" + *frame + "'");
  }
}

}  // namespace

std::string defaultBaseFrame(const std::string& node_namespace) {
  const std::size_t first = node_namespace.find_first_not_of('/');
  return first == std::string::npos ? "base_link" : node_namespace.substr(first) + "/base_link";
}

PlannerFrames readPlannerFrames(const ros::NodeHandle& private_nh, const std::string& node_namespace) {
  PlannerFrames frames;
  frames.base_frame = defaultBaseFrame(node_namespace);
  readFrame(private_nh, "map_frame", &frames.map_frame);
  readFrame(private_nh, "base_frame", &frames.base_frame);
  return frames;
}

OmplNodeParameters readOmplNodeParameters(const ros::NodeHandle& private_nh) {
  OmplNodeParameters parameters;
  readParameter(private_nh, "planner", &parameters.planner.planner, "a string: RRTConnect, RRTstar or PRM");
  readParameter(private_nh, "planning_time", &parameters.planner.planning_time, "a number of seconds");
  int seed = static_cast<int>(parameters.seed);
  readParameter(private_nh, "seed", &seed, "an integer in [1, 2147483647]");
  if (seed < 1) throw InvalidArgument("~seed", "expected an integer in [1, 2147483647], got " + std::to_string(seed));
  parameters.seed = static_cast<std::uint32_t>(seed);
  readParameter(private_nh, "unknown_is_free", &parameters.unknown_is_free, "true or false");
  try {
    parameters.planner.validate();
  } catch (const InvalidArgument& e) {
    throw InvalidArgument("~" + e.name(), e.problem());
  }
  return parameters;
}

}  // namespace planners
}  // namespace ppp
