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
  if (!readParameter(nh, "type", &config.type, "a string, one of: " + typeList())) {
    throw InvalidArgument("~type", "required; valid: " + typeList());
  }
  config.name = default_name;
  readParameter(nh, "name", &config.name, "a string");
  if (config.name.empty()) throw InvalidArgument("~name", "expected a non-empty agent name");
  std::string memory = "full";
  readParameter(nh, "memory", &memory, "a string: KxK with odd K (e.g. 5x5) or 'full'");
  config.memory_window = parseMemoryWindow(memory, "~memory");
  readParameter(nh, "sensor_noise", &config.sensor_noise, "a number (a probability in [0, 1])");
  try {
    config.validate();
  } catch (const InvalidArgument& e) {
    throw InvalidArgument("~" + e.name(), std::string(e.what()).substr(e.name().size() + 2));
  }
  if (isPlanner(config)) {
    throw InvalidArgument("~type", "planner agents run through planner_bridge_node, not agent_node; valid here: " +
                                       typeList());
  }
  return config;
}

}  // namespace agents
}  // namespace ppp
