#pragma once

#include <string>

#include <ros/node_handle.h>

#include "ppp_agents/agent_config.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace agents {

/// Reads and validates the agent node's private parameters: `~type` (required), `~name` (default
/// `default_name`), `~memory` ("KxK" or "full", default full) and `~sensor_noise` (default 0).
/// @throws InvalidArgument naming the parameter ("~type: unknown agent type 'x'; valid: ...").
AgentConfig readAgentNodeParameters(const ros::NodeHandle& private_nh, const std::string& default_name);

/// Reads an optional parameter of type T; a present parameter of another type is an error naming `~name` and
/// what was `expected`. Returns whether it was present.
template <typename T>
bool readParameter(const ros::NodeHandle& nh, const std::string& name, T* value, const std::string& expected) {
  if (!nh.hasParam(name)) return false;
  if (!nh.getParam(name, *value)) throw InvalidArgument("~" + name, "expected " + expected);
  return true;
}

/// The last component of a graph name ("/ns/explorer" -> "explorer").
std::string baseName(const std::string& graph_name);

}  // namespace agents
}  // namespace ppp
