#include "planner_bridge_parameters.hpp"

#include "agent_node_parameters.hpp"
#include "planner_bridge_messages.hpp"
#include "ppp_core/error.hpp"
#include "ppp_msgs/node_parameters.h"

namespace ppp {
namespace agents {

using ppp_msgs::readParameter;

BridgeParameters readBridgeParameters(const ros::NodeHandle& nh, const std::string& ns) {
  BridgeParameters p;
  p.config.type = kPlannerType;
  p.config.name = baseName(ns);
  static const std::vector<OptionSpec<AgentConfig>> agent_specs =
      selectOptions(agentOptionSpecs(), {"name", "memory", "sensor_noise"});
  ppp_msgs::readOptionParameters(nh, agent_specs, &p.config);
  if (p.config.name.empty()) {
    throw InvalidArgument("~name", "required when the bridge runs outside an agent's namespace (e.g. ns=\"ompl\")");
  }
  readParameter(nh, "resolution", &p.resolution, "a number of metres per cell");
  readParameter(nh, "plan_timeout", &p.plan_timeout, "a number of seconds");
  readParameter(nh, "connect_timeout", &p.connect_timeout, "a number of seconds");
  readParameter(nh, "map_frame", &p.map_frame, "a frame name");
  p.base_frame = bareFrame(ns == "/" ? "robot/base_link" : ns + "/robot/base_link");
  readParameter(nh, "base_frame", &p.base_frame, "a frame name");
  ppp_msgs::requirePositive(p.resolution, "~resolution");
  ppp_msgs::requirePositive(p.plan_timeout, "~plan_timeout");
  ppp_msgs::requirePositive(p.connect_timeout, "~connect_timeout");
  p.map_frame = bareFrame(p.map_frame);
  p.base_frame = bareFrame(p.base_frame);
  if (p.map_frame.empty()) throw InvalidArgument("~map_frame", "expected a non-empty frame name");
  if (p.base_frame.empty()) throw InvalidArgument("~base_frame", "expected a non-empty frame name");
  ppp_msgs::validateParameters(p.config);
  return p;
}

}  // namespace agents
}  // namespace ppp
