#include "ppp_agents/continuous/continuous_agent.hpp"

#include <string>

#include "ppp_agents/continuous/continuous_astar.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/motion_options.hpp"

namespace ppp {
namespace agents {

void checkContinuousAgent(const AgentConfig& config, const EpisodeOptions& options) {
  if (playsContinuously(config, options) && !isPlanner(config)) makeContinuousAgent(config);
}

void refuseContinuous(const AgentConfig& config, const EpisodeOptions& options) {
  if (!playsContinuously(config, options)) return;
  throw InvalidArgument("motion", "agent '" + config.name + "' plays in " + std::string(kMotionContinuous) +
                                      " motion, which experiments (in process and through ROS), `ppp simulate` and "
                                      "`ppp replay` play, and hunts and shrinks only with planner agents (through ROS)");
}

bool movesContinuously(const AgentConfig& config) { return config.type == "astar"; }

std::unique_ptr<ContinuousAgent> makeContinuousAgent(const AgentConfig& config) {
  if (movesContinuously(config)) return std::make_unique<ContinuousAstar>();
  throw InvalidArgument("motion", "agent '" + config.name + "' (" + config.type + ") moves only on the grid: " +
                                      std::string(kMotionContinuous) + " motion plays astar");
}

}  // namespace agents
}  // namespace ppp
