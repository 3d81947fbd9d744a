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

/// A continuous run of PPP `problem` (decoded as `grid`) whose shortest route for the disc takes `optimal` moves
/// (continuousOptimalMoves()), seeded `run_seed`: its budget from `options`. @throws InvalidArgument naming
/// robot_radius when the disc cannot stand at the start.
ContinuousEpisode continuousEpisode(const Problem& problem, const Grid& grid, const EpisodeOptions& options,
                                    int optimal, std::uint64_t run_seed, bool record_poses = false);

/// The longest budget of simulated time, in seconds, of a continuous run of any PPP of `sets` under `options`.
double longestContinuousRun(const std::vector<PreparedSet>& sets, const EpisodeOptions& options);

/// What an agent of `config` is told at the start of `episode` (a run of a PPP decoded as `grid`, seeded
/// `run_seed`): the true map only when the agent is given it (astar).
ContinuousStart continuousStart(const ContinuousEpisode& episode, const EpisodeOptions& options,
                                const AgentConfig& config, const Grid& grid, std::uint64_t run_seed);

/// The results.csv row of run `run` (seeded `seed`) of `agent` on PPP `problem` of `set`, which went as `outcome`
/// and whose shortest route for the disc takes `optimal` moves: steps are control periods, bumps 0, path and
/// optimal lengths in cells (the distance travelled / resolution; `optimal`), the diagnosis from its cells.
EpisodeResult continuousResult(const PreparedSet& set, int problem, const std::string& agent, int run,
                               std::uint64_t seed, int optimal, const ContinuousOutcome& outcome,
                               const EpisodeOptions& options);

/// The run of a PPP (decoded as `grid`, with `grid_moves` fewest moves on the grid) seeded `run_seed` played again
/// from its recorded `commands` (EpisodeResult::commands), with its poses: ended as `end_reason` where the commands
/// run out before the world ends it (a planner's failure). @throws Error naming the agent `agent` and the seed when
/// the commands do not give a run that ends as `end_reason` after them all.
ContinuousOutcome recordedContinuousRun(const Problem& problem, const Grid& grid, const EpisodeOptions& options,
                                        int grid_moves, std::uint64_t run_seed,
                                        const std::vector<BodyVelocity>& commands, const std::string& end_reason,
                                        const std::string& agent);

/// Plays one agent configuration's runs in continuous motion in process (ContinuousEpisode), one at a time.
class ContinuousRunner {
 public:
  /// A runner for `config` under `options`. @throws InvalidArgument as checkContinuousAgent().
  ContinuousRunner(const AgentConfig& config, const EpisodeOptions& options);
  /// One run of PPP `problem` (decoded as `grid`, with `grid_moves` fewest moves on the grid) seeded `run_seed`.
  ContinuousOutcome run(const Problem& problem, const Grid& grid, int grid_moves, std::uint64_t run_seed,
                        bool record_poses = false);
  /// Run `run_number` of PPP `problem` of `set` as its results.csv row (continuousResult()).
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
