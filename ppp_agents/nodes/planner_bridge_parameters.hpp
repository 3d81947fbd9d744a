#pragma once

#include <string>

#include <ros/node_handle.h>

#include "ppp_agents/agent_config.hpp"
#include "ppp_agents/planner_bridge_options.hpp"

namespace ppp {
namespace agents {

/// The planner bridge's `~` parameters: its agent (name and memory handicap, type planner) and its own options.
struct BridgeParameters : BridgeOptions {
  AgentConfig config;  ///< Agent name and memory handicap (type planner).
};

/// Reads and checks the bridge's parameters; `ns` is the node's namespace (default name and base frame).
/// @throws InvalidArgument naming the parameter.
BridgeParameters readBridgeParameters(const ros::NodeHandle& private_nh, const std::string& ns);

}  // namespace agents
}  // namespace ppp
