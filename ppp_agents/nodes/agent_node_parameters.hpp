#pragma once

#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "ppp_agents/agent_config.hpp"
#include "ppp_core/error.hpp"
#include "ppp_msgs/node_parameters.h"

namespace ppp {
namespace agents {

/// Reads and validates the agent node's private parameters: `~type` (required), `~name` (default
/// `default_name`), `~memory` ("KxK" or "full", default full) and `~sensor_noise` (default 0).
/// @throws InvalidArgument naming the parameter ("~type: unknown agent type 'x'; valid: ...").
AgentConfig readAgentNodeParameters(const ros::NodeHandle& private_nh, const std::string& default_name);

/// The last component of a graph name ("/ns/explorer" -> "explorer").
std::string baseName(const std::string& graph_name);

}  // namespace agents
}  // namespace ppp
