#pragma once

#include <cstdint>

#include "ppp_agents/agent.hpp"
#include "ppp_agents/agent_config.hpp"
#include "ppp_core/episode.hpp"
#include "ppp_core/episode_options.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/sensor.hpp"
#include "ppp_core/window_atlas.hpp"

namespace ppp {
namespace agents {

/// The EpisodeInfo an agent is given at the start of a run of `problem` under the move model with
/// `connectivity`: a prior map only for astar, which plans in the robot's configuration space `motion` when it
/// has one, and planners with prior_map, which get the true `grid` (their inflation is theirs).
EpisodeInfo episodeInfo(const Problem& problem, const Grid& grid, const AgentConfig& config, std::uint64_t run_seed,
                        Connectivity connectivity, const Grid* motion = nullptr);

/// Runs episodes in process: the move model (Episode, in the robot's configuration space), scans by SensorModel
/// with the agent's noise, the budget.
/// Holds the sensor and buffers, so reuse one runner for many episodes of one agent configuration.
class EpisodeRunner {
 public:
  /// A runner for one agent configuration. @throws InvalidArgument for bad options.
  EpisodeRunner(const AgentConfig& config, const EpisodeOptions& options);
  /// Runs `agent` from the start of `problem` (whose decoded grid is `grid`, and `windows` its atlas when
  /// there is one) with the given run seed.
  EpisodeOutcome run(const Problem& problem, const Grid& grid, Agent& agent, std::uint64_t run_seed,
                     bool record_path = false, const WindowAtlas* windows = nullptr);
  /// The sensor of this configuration (range from the options, noise from the agent).
  const SensorModel& sensor() const { return sensor_; }

 private:
  AgentConfig config_;
  EpisodeOptions options_;
  SensorModel sensor_;
};

/// One episode of a fresh agent of `config` with `run_seed`, its path recorded (a run of results.csv replayed).
EpisodeOutcome recordEpisode(const Problem& problem, const Grid& grid, const AgentConfig& config,
                             const EpisodeOptions& options, std::uint64_t run_seed);

}  // namespace agents
}  // namespace ppp
