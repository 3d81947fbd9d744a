#include "ppp_agents/agent_registry.hpp"

#include "ppp_agents/agent_config.hpp"
#include "ppp_agents/astar_agent.hpp"
#include "ppp_agents/bumper_agent.hpp"
#include "ppp_agents/explorer_agent.hpp"
#include "ppp_agents/random_agent.hpp"
#include "ppp_agents/wall_follower_agent.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {
namespace agents {

const std::vector<AgentType>& agentRegistry() {
  // Sensor noise is applied by the sensor; the agents only see its effect in their scans.
  static const std::vector<AgentType> registry = {
      {"astar", "A* on the true map, follows the plan (the control)",
       AgentTrait::ReadsScanWindow | AgentTrait::NeedsPriorMap | AgentTrait::Control,
       [](const AgentBehaviour& b) -> std::unique_ptr<Agent> { return std::make_unique<AstarAgent>(b); }},
      {"random", "uniform over the five actions (the baseline); by design it never looks for the goal",
       AgentTrait::Baseline,
       [](const AgentBehaviour& b) -> std::unique_ptr<Agent> { return std::make_unique<RandomAgent>(b); }},
      {"wall_follower_left", "heads for the goal, then keeps the first wall met on its left",
       AgentTrait::ReadsScanWindow | AgentTrait::SeeksGoal | AgentTrait::FollowsWalls,
       [](const AgentBehaviour& b) -> std::unique_ptr<Agent> {
         return std::make_unique<WallFollowerAgent>(WallFollowerAgent::Side::Left, b);
       }},
      {"wall_follower_right", "heads for the goal, then keeps the first wall met on its right",
       AgentTrait::ReadsScanWindow | AgentTrait::SeeksGoal | AgentTrait::FollowsWalls,
       [](const AgentBehaviour& b) -> std::unique_ptr<Agent> {
         return std::make_unique<WallFollowerAgent>(WallFollowerAgent::Side::Right, b);
       }},
      {"explorer", "moves to the neighbour revealing most unknown cells",
       AgentTrait::ReadsScanWindow | AgentTrait::SeeksGoal | AgentTrait::Explores,
       [](const AgentBehaviour& b) -> std::unique_ptr<Agent> { return std::make_unique<ExplorerAgent>(false, b); }},
      {"long_term_explorer", "the explorer, walking to the nearest frontier when nothing is new nearby",
       AgentTrait::ReadsScanWindow | AgentTrait::SeeksGoal | AgentTrait::Explores | AgentTrait::SeeksFrontiers,
       [](const AgentBehaviour& b) -> std::unique_ptr<Agent> { return std::make_unique<ExplorerAgent>(true, b); }},
      {"bumper", "straight until a bump, then a random new direction",
       AgentTrait::ReadsScanWindow | AgentTrait::SeeksGoal | AgentTrait::Bumps,
       [](const AgentBehaviour& b) -> std::unique_ptr<Agent> { return std::make_unique<BumperAgent>(false, b); }},
      {"decision_bumper", "the bumper, trying untried directions at each bump cell first",
       AgentTrait::ReadsScanWindow | AgentTrait::SeeksGoal | AgentTrait::Bumps,
       [](const AgentBehaviour& b) -> std::unique_ptr<Agent> { return std::make_unique<BumperAgent>(true, b); }},
      {kPlannerType, "an external ROS planner played through planner_bridge_node", AgentTrait::ReadsScanWindow,
       nullptr},
  };
  return registry;
}

const AgentType* findAgentType(const std::string& name) {
  for (const AgentType& type : agentRegistry()) {
    if (name == type.name) return &type;
  }
  return nullptr;
}

const AgentType& agentType(const std::string& name) {
  const AgentType* type = findAgentType(name);
  if (type == nullptr) throw InvalidArgument("type", "unknown agent type '" + name + "'; valid: " + agentTypeList());
  return *type;
}

std::string agentTypeList() {
  std::vector<std::string> names;
  for (const AgentType& type : agentRegistry()) names.push_back(type.name);
  return joinNames(names);
}

std::unique_ptr<Agent> makeAgent(const AgentConfig& config) {
  config.validate();
  const AgentType& type = agentType(config.type);
  if (type.make == nullptr) {
    throw InvalidArgument("type", "'" + config.name + "' is a planner agent: an external ROS planner played through "
                                  "planner_bridge_node (docs/reference/planner-interface.md), never built in-process");
  }
  return type.make(agentBehaviour(config));
}

bool seeksGoal(const AgentConfig& config) {
  if (config.goal_seeking == kGoalSeekingByType) return agentType(config.type).has(AgentTrait::SeeksGoal);
  return config.goal_seeking == kGoalSeekingOn;
}

AgentBehaviour agentBehaviour(const AgentConfig& config) {
  AgentBehaviour behaviour;
  const bool scans = config.memory_model == kMemoryModelScans;
  behaviour.memory_window = scans ? 0 : config.memory_window;
  behaviour.memory_scans = scans ? config.memory_window * config.memory_window : 0;
  behaviour.seek_goal = seeksGoal(config);
  behaviour.goal_range = config.goal_range;
  behaviour.random_wall_start = config.wall_start == kWallStartRandom;
  behaviour.leave_wall_for_goal = config.wall_leave == kWallLeaveGoalFree;
  behaviour.random_goal_ties = config.goal_ties == kGoalTiesRandom;
  behaviour.walls_by_touch = config.wall_sense == kWallSenseTouch;
  behaviour.quarter_turns = config.bumper_turn == kBumperTurnQuarter;
  behaviour.goal_ties_for_gain = config.explorer_ties == kExplorerTiesGoal;
  behaviour.idle_least_visited = config.explorer_idle == kExplorerIdleLeastVisited;
  behaviour.frontier_towards_goal = config.frontier == kFrontierGoal;
  return behaviour;
}

bool readsScanWindow(const AgentConfig& config) {
  return agentType(config.type).has(AgentTrait::ReadsScanWindow) || seeksGoal(config);
}

bool givenPriorMap(const AgentConfig& config) {
  return agentType(config.type).has(AgentTrait::NeedsPriorMap) || (isPlanner(config) && config.prior_map);
}

}  // namespace agents
}  // namespace ppp
