#include "agent_node_parameters.hpp"

#include "ppp_core/error.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {
namespace agents {

namespace {

std::string typeList() { return joinNames(agentTypeNames()); }

}  // namespace

std::string baseName(const std::string& graph_name) {
  const std::size_t slash = graph_name.rfind('/');
  return slash == std::string::npos ? graph_name : graph_name.substr(slash + 1);
}

AgentConfig readAgentNodeParameters(const ros::NodeHandle& nh, const std::string& default_name) {
  AgentConfig config;
  config.name = default_name;
  ppp_msgs::readOptionParameters(nh, agentNodeOptionSpecs(), &config);
  if (config.type.empty()) throw ppp_msgs::parameterError(InvalidArgument("type", "required; valid: " + typeList()));
  ppp_msgs::validateParameters(config);
  if (isPlanner(config)) {
    throw ppp_msgs::parameterError(InvalidArgument(
        "type", "planner agents run through planner_bridge_node, not agent_node; valid here: " + typeList()));
  }
  return config;
}

}  // namespace agents
}  // namespace ppp
