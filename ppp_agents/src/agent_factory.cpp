#include <memory>

#include "ppp_agents/agent_config.hpp"
#include "ppp_agents/astar_agent.hpp"
#include "ppp_agents/bumper_agent.hpp"
#include "ppp_agents/explorer_agent.hpp"
#include "ppp_agents/random_agent.hpp"
#include "ppp_agents/wall_follower_agent.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace agents {

std::unique_ptr<Agent> makeAgent(const AgentConfig& config) {
  config.validate();
  const std::string& type = config.type;
  const int window = config.memory_window;
  // Sensor noise is applied by the sensor; the agents only see its effect in their scans.
  if (type == "astar") return std::make_unique<AstarAgent>(window);
  if (type == "random") return std::make_unique<RandomAgent>(window);
  if (type == "wall_follower_left") return std::make_unique<WallFollowerAgent>(WallFollowerAgent::Side::Left, window);
  if (type == "wall_follower_right") {
    return std::make_unique<WallFollowerAgent>(WallFollowerAgent::Side::Right, window);
  }
  if (type == "explorer") return std::make_unique<ExplorerAgent>(false, window);
  if (type == "long_term_explorer") return std::make_unique<ExplorerAgent>(true, window);
  if (type == "bumper") return std::make_unique<BumperAgent>(false, window);
  if (type == "decision_bumper") return std::make_unique<BumperAgent>(true, window);
  if (isPlanner(config)) {
    throw InvalidArgument("type", "'" + config.name + "' is a planner agent: an external ROS planner played through "
                                  "planner_bridge_node (docs/planner-interface.md), never built in-process");
  }
  throw InvalidArgument("type", "no agent is built for type '" + type + "'");  // validate() lists the types
}

bool readsScanWindow(const AgentConfig& config) { return config.type != "random"; }

}  // namespace agents
}  // namespace ppp
