#pragma once

#include <string>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_core/episode_options.hpp"
#include "ppp_simulator/report/pass_rates.hpp"

namespace ppp {
namespace simulator {

/// One agent played in both motion models: its configuration on the grid and its configuration in continuous
/// motion (the report's "Both motion models").
struct MotionPair {
  std::string grid_agent;        ///< The agent on the grid.
  std::string continuous_agent;  ///< The same agent in continuous motion.
};

/// For each agent of `agents` that plays in continuous motion under `episode`, the first agent on the grid that
/// is the same but for its motion (type, planner_node and planner_args equal), else the first with the same type
/// and planner_node (a planner may be tuned for each model), when there is one; in the order of `agents`.
std::vector<MotionPair> motionPairs(const std::vector<agents::AgentConfig>& agents, const EpisodeOptions& episode);

/// How `row`'s failed runs ended, most first, e.g. "120 stuck, 30 collision, 2 loop" ("none" when none failed):
/// each diagnosis kind, with `reported` split into its collisions and the other reasons a run reported.
std::string failureKinds(const SetPassRate& row);

}  // namespace simulator
}  // namespace ppp
