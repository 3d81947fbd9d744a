#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_agents/continuous/continuous_agent.hpp"
#include "ppp_agents/episode_result.hpp"
#include "ppp_agents/prepared_set.hpp"
#include "ppp_core/continuous_episode.hpp"
#include "ppp_core/episode_options.hpp"

namespace ppp {
namespace agents {

/// @throws InvalidArgument naming "robot_radius" when the disc of `options` cannot stand at the start of PPP
/// `problem` of `set` in continuous motion.
void checkContinuousStart(const PreparedSet& set, int problem, const EpisodeOptions& options);

/// A continuous run's shortest route in moves: the fewest 4-connected moves through the cell centres of the disc's
/// configuration space, or, where the disc has no route, the PPP's `grid_moves`.
int continuousOptimalMoves(const Problem& problem, const Grid& grid, const EpisodeOptions& options, int grid_moves);

/// Plays one agent configuration's runs in continuous motion in process (ContinuousEpisode), one at a time.
class ContinuousRunner {
 public:
  /// A runner for `config` under `options`. @throws InvalidArgument as checkContinuousAgent().
  ContinuousRunner(const AgentConfig& config, const EpisodeOptions& options);
  /// One run of PPP `problem` (decoded as `grid`, with `grid_moves` fewest moves on the grid) seeded `run_seed`.
  ContinuousOutcome run(const Problem& problem, const Grid& grid, int grid_moves, std::uint64_t run_seed,
                        bool record_poses = false);
  /// Run `run_number` of PPP `problem` of `set` as its results.csv row: steps are control periods, bumps 0, path and optimal
  /// lengths in cells (the distance travelled / resolution; the disc's fewest moves).
  EpisodeResult row(const PreparedSet& set, int problem, int run_number, std::uint64_t run_seed);

 private:
  /// One run whose shortest route for the disc takes `optimal` moves.
  ContinuousOutcome play(const Problem& problem, const Grid& grid, int optimal, std::uint64_t run_seed,
                         bool record_poses);

  AgentConfig config_;
  EpisodeOptions options_;
  std::unique_ptr<ContinuousAgent> agent_;
  std::vector<float> ranges_;
};

}  // namespace agents
}  // namespace ppp
