#pragma once

#include <string>

#include <ros/node_handle.h>

#include "ppp_agents/agent_config.hpp"

namespace ppp {
namespace agents {

/// The planner bridge's `~` parameters.
struct BridgeParameters {
  AgentConfig config;           ///< Agent name and memory handicap (type planner).
  double resolution = 1.0;      ///< Metres per cell of the published map.
  double plan_timeout = 5.0;    ///< Seconds the planner has to answer a plan request.
  double connect_timeout = 20.0;  ///< Seconds to wait at start-up for the planner's topics.
  std::string map_frame = "map";  ///< Frame of the map, poses and goal.
  std::string base_frame;       ///< The robot's frame (tf child, odom child, scan frame).
};

/// Reads and checks the bridge's parameters; `ns` is the node's namespace (default name and base frame).
/// @throws InvalidArgument naming the parameter.
BridgeParameters readBridgeParameters(const ros::NodeHandle& private_nh, const std::string& ns);

}  // namespace agents
}  // namespace ppp
