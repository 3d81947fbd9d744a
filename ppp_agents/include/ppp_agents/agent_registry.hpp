#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ppp_agents/agent.hpp"

namespace ppp {
namespace agents {

/// Everything the system knows about one agent type: the one place an agent type is named.
struct AgentType {
  const char* name;                 ///< The type as configurations name it ("explorer").
  const char* description;          ///< One line for help texts.
  bool reads_scan_window;           ///< False: the simulator sends it no window (it never looks).
  bool needs_prior_map;             ///< True: it is given the true map at the start of each episode.
  bool is_control;                  ///< The control: passes every valid PPP (left out when ranking PPPs).
  bool is_baseline;                 ///< No strategy to find faults in (left out of the report's worst PPPs).
  /// Builds one agent with a memory window (0: full); null for planner agents, which are external ROS planners.
  std::unique_ptr<Agent> (*make)(int memory_window);
};

/// Every agent type, the built-in ones first, then `planner`.
const std::vector<AgentType>& agentRegistry();

/// The entry of `name`, or null when there is none.
const AgentType* findAgentType(const std::string& name);

/// The entry of `name`. @throws InvalidArgument("type", ...) listing the valid types.
const AgentType& agentType(const std::string& name);

/// Every type's name, comma-separated (for messages).
std::string agentTypeList();

}  // namespace agents
}  // namespace ppp
