#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_core/movingai_scen.hpp"
#include "ppp_agents/episode_runner.hpp"

namespace ppp {
namespace simulator {

/// How to play a MovingAI scenario file.
struct ScenarioRunOptions {
  agents::AgentConfig agent;  ///< The agent, played once per scenario.
  EpisodeOptions episode;     ///< Sensor range; its budget only when `budget_given`.
  bool budget_given = false;  ///< False: each scenario's budget is scenarioBudget() of its map.
  std::uint64_t seed = 1;     ///< Scenario i runs with deriveSeed(seed, {i}).
  std::string map_dir;        ///< Where else to look for the maps (findScenarioMap); may be empty.
};

/// One scenario played.
struct ScenarioResult {
  MovingAiScenario scenario;  ///< As read from the file.
  EpisodeOutcome outcome;     ///< The agent's episode (4-connected moves: its path length is its moves).
  std::uint64_t seed = 0;     ///< The run seed.
  int budget = 0;             ///< The move budget it had.
};

/// The default move budget on a map: its free cells (every simple path fits), at least 1, at most the episode
/// engine's largest budget.
int scenarioBudget(const Grid& grid);

/// Plays the agent once on every scenario of the `.scen` file, in file order (each map read once).
/// @throws IoError (a file, or a map not found), ParseError (naming the .scen's or the map's line, including a
/// scenario off its map, on an obstacle or with start = goal), InvalidArgument for bad options.
std::vector<ScenarioResult> runScenarios(const std::string& scen_path, const ScenarioRunOptions& options);

}  // namespace simulator
}  // namespace ppp
