#include "ppp_agents/episode_runner.hpp"

#include "ppp_agents/continuous/continuous_agent.hpp"
#include "ppp_core/footprint.hpp"
#include "ppp_core/optimum.hpp"

namespace ppp {
namespace agents {

EpisodeInfo episodeInfo(const Problem& problem, const Grid& grid, const AgentConfig& config, std::uint64_t run_seed,
                        Connectivity connectivity, const Grid* motion) {
  EpisodeInfo info;
  info.connectivity = connectivity;
  info.width = grid.width();
  info.height = grid.height();
  info.start = problem.start;
  info.goal = problem.goal;
  info.seed = agentSeed(run_seed);
  info.prior_map = !givenPriorMap(config) ? nullptr : isPlanner(config) || motion == nullptr ? &grid : motion;
  return info;
}

EpisodeRunner::EpisodeRunner(const AgentConfig& config, const EpisodeOptions& options)
    : config_((config.validate(), config)),
      options_((options.validate(), refuseContinuous(config, options), options)),
      sensor_(SensorOptions{options.sensor_range, config.sensor_noise}) {}

EpisodeOutcome EpisodeRunner::run(const Problem& problem, const Grid& grid, Agent& agent,
                                  std::uint64_t run_seed, bool record_path, const WindowAtlas* windows) {
  Grid space;
  const Grid* motion = &motionGrid(grid, options_.robot_radius, &space);
  agent.reset(episodeInfo(problem, grid, config_, run_seed, options_.connectivity, motion));
  Episode episode(problem, grid, sensor_, run_seed, options_.budgetRule(episodeBudget(options_, problem, grid)),
                  options_.connectivity,
                  record_path, windows, motion);
  while (!episode.done()) episode.apply(agent.act(episode.scan()));
  return episode.takeOutcome();
}

EpisodeOutcome recordEpisode(const Problem& problem, const Grid& grid, const AgentConfig& config,
                             const EpisodeOptions& options, std::uint64_t run_seed) {
  EpisodeRunner runner(config, options);
  auto agent = makeAgent(config);
  return runner.run(problem, grid, *agent, run_seed, true);
}

}  // namespace agents
}  // namespace ppp
