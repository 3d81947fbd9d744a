#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ppp_agents/agent.hpp"

namespace ppp {
namespace agents {

/// What the simulator and the report need to know of an agent type; combined with `|`.
enum class AgentTrait : unsigned {
  None = 0,                  ///< None of the below.
  ReadsScanWindow = 1u << 0, ///< The simulator sends it the scan window (without it, it never looks).
  NeedsPriorMap = 1u << 1,   ///< It is given the true map at the start of each episode.
  Control = 1u << 2,         ///< The control: passes every valid PPP (left out when ranking PPPs).
  Baseline = 1u << 3,        ///< No strategy to find faults in (left out of the report's worst PPPs).
  SeeksGoal = 1u << 4,       ///< By design it heads for the goal once it has seen it (goal_seeking: by_type).
  FollowsWalls = 1u << 5,    ///< A wall follower: it takes wall_start, wall_leave, goal_ties and wall_sense.
  Explores = 1u << 6,        ///< An explorer: it takes explorer_idle and explorer_ties.
  Bumps = 1u << 7,           ///< A bumper: it takes bumper_turn.
  SeeksFrontiers = 1u << 8,  ///< The long-term explorer: it takes frontier.
};

/// Both traits.
constexpr AgentTrait operator|(AgentTrait a, AgentTrait b) {
  return static_cast<AgentTrait>(static_cast<unsigned>(a) | static_cast<unsigned>(b));
}

/// Everything the system knows about one agent type: the one place an agent type is named.
struct AgentType {
  const char* name;                 ///< The type as configurations name it ("explorer").
  const char* description;          ///< One line for help texts.
  AgentTrait traits;                ///< What the simulator and the report need to know of it.
  /// Builds one agent of this type playing with `behaviour`; null for planner agents, which are external ROS
  /// planners.
  std::unique_ptr<Agent> (*make)(const AgentBehaviour& behaviour);
  /// Whether the type has `trait`.
  bool has(AgentTrait trait) const { return (static_cast<unsigned>(traits) & static_cast<unsigned>(trait)) != 0; }
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
