#include "planner_bridge_parameters.hpp"

#include "agent_node_parameters.hpp"
#include "planner_bridge_messages.hpp"
#include "ppp_core/error.hpp"
#include "ppp_msgs/node_parameters.h"

namespace ppp {
namespace agents {

BridgeParameters readBridgeParameters(const ros::NodeHandle& nh, const std::string& ns) {
  BridgeParameters p;
  p.config.type = kPlannerType;
  p.config.name = baseName(ns);
  static const std::vector<OptionSpec<AgentConfig>> agent_specs =
      selectOptions(agentOptionSpecs(), {"name", "memory", "sensor_noise"});
  ppp_msgs::readOptionParameters(nh, agent_specs, &p.config);
  if (p.config.name.empty()) {
    throw ppp_msgs::parameterError(
        InvalidArgument("name", "required when the bridge runs outside an agent's namespace (e.g. ns=\"ompl\")"));
  }
  BridgeOptions& options = p;
  ppp_msgs::readOptionParameters(nh, bridgeOptionSpecs(), &options);
  options.map_frame = bareFrame(options.map_frame);
  options.base_frame = bareFrame(options.base_frame.empty() ? defaultBridgeBaseFrame(ns) : options.base_frame);
  ppp_msgs::validateParameters(options);
  ppp_msgs::validateParameters(p.config);
  return p;
}

}  // namespace agents
}  // namespace ppp
