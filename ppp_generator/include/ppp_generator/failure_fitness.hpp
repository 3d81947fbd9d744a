#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_core/episode_options.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_generator/fitness.hpp"
#include "ppp_generator/generator_options.hpp"

namespace ppp {
namespace generator {

/// Most worker threads a panel fitness or an experiment may ask for.
constexpr int kMaxThreads = 1024;

/// The agents and rules of a panel fitness, `failure` or `regret`.
struct FailurePanel {
  std::string fitness = kFailureFitness;    ///< kFailureFitness or kRegretFitness: what the panel's runs score.
  std::vector<agents::AgentConfig> agents;  ///< The panel, each run `runs_per_eval` times per PPP.
  EpisodeOptions episode;                   ///< Budget and sensor range of the episodes.
  int runs_per_eval = 20;                   ///< Episodes per agent per PPP.
  int round_size = kFailureBatchSize;       ///< PPPs scored per call (matings per round of the generator).
  std::uint64_t seed = 1;                   ///< The generator seed the run seeds derive from.
  int threads = 0;                          ///< Worker threads; 0 = every core.
  /// Whether the estimates carry the failed runs' signatures (an archive keyed by them reads them; signing a
  /// failed run costs about a tenth of playing a built-in agent's, so a hunt without that archive skips it).
  bool signatures = true;
};

/// The seed of run `run` of panel agent `agent` on a PPP whose grid hashes to `grid_hash`: the same PPP is
/// always judged on the same runs (common random numbers), whatever the batch, thread or mating it came in.
std::uint64_t failureRunSeed(std::uint64_t generator_seed, std::uint64_t grid_hash, const std::string& agent,
                             int run);

/// One PPP's failure figures.
struct FailureEstimate {
  double failure_rate = 0;  ///< Mean over the panel of each agent's share of failed runs (soft failures included).
  double budget_used = 0;   ///< Mean share of the budget the panel's runs used.
  double regret = 0;        ///< Mean over the panel of each agent's mean regret (runRegret()).
  std::map<std::string, int> signatures{};  ///< Failed and soft-failed runs per failure signature.
  long steps = 0;  ///< Steps the panel's runs took: moves on the grid, control periods in continuous motion.
};

/// What a panel's runs on one PPP came to, per panel agent.
struct PanelTally {
  /// An empty tally of a panel of `agents`.
  explicit PanelTally(std::size_t agents = 0)
      : failures(agents, 0), steps(agents, 0), regret(agents, 0), played(agents, 0) {}
  std::vector<int> failures;   ///< Failed runs (soft failures included).
  std::vector<long> steps;     ///< Moves used: a run's steps, or its whole budget when it failed.
  std::vector<double> regret;  ///< Sum of the runs' regrets.
  std::vector<long> played;    ///< Steps the runs took (moves, or control periods), whatever their outcome.
  /// Adds a run of panel agent `agent` that `passed` (false for a soft failure too) after `steps`, on a PPP with
  /// move budget `budget` and fewest moves `optimal_moves`.
  void add(std::size_t agent, bool passed, int steps, int budget, int optimal_moves);
};

/// The figures of a tally of `runs` runs per agent with move budget `budget`.
FailureEstimate estimateOf(const PanelTally& tally, int runs, int budget);

/// The score of a panel fitness (`failure` or `regret`) from a PPP's figures.
FitnessScore panelScore(const std::string& fitness, const FailureEstimate& estimate);

/// Plays every panel agent runs_per_eval times on each PPP (in parallel over PPPs and agents) and returns
/// the figures in input order. @throws InvalidArgument for a planner agent (those run only through ROS).
std::vector<FailureEstimate> estimateFailures(const FailurePanel& panel, const std::vector<const Problem*>& problems,
                                              const std::vector<const Grid*>& grids);

/// The panel's fitness, maximised: for `failure`, value = the failure rate, score = failureScore(); for
/// `regret`, value = the mean regret, score = regretScore(). Scores round_size PPPs per call.
/// @throws InvalidArgument naming "fitness", "agents" (an empty panel or a planner agent), "runs_per_eval", "round_size",
/// "threads" or an episode option.
Fitness makeFailureFitness(const FailurePanel& panel);

/// The episode options a hunt takes besides the generator's: all but robot_radius, which is the generator's
/// (`ppp generate`'s episode flags).
const std::vector<OptionSpec<EpisodeOptions>>& huntEpisodeOptionSpecs();

/// The fitness of a set's generator options: makeFitness(options.fitness), or for a panel fitness (`failure`,
/// `regret`) the panel options.agents looked up in `available` (see resolvePanel), played with `episode`'s
/// rules on the generator's robot (options.robot_radius) on `threads` threads (0: every core).
/// @throws InvalidArgument naming the option.
Fitness fitnessFor(const GeneratorOptions& options, const std::vector<agents::AgentConfig>& available,
                   const EpisodeOptions& episode, int threads);

/// fitnessFor() with the panel looked up in options.agents_file (an agents list), or among the built-in agent types
/// when it is empty: what `ppp generate` and a generator node hunting in process play.
/// @throws InvalidArgument naming the option, IoError or ParseError for the agents file.
Fitness fitnessFor(const GeneratorOptions& options, const EpisodeOptions& episode, int threads);

/// Looks up the panel `names` among `available` configurations (an experiment's agents or an agents file);
/// with no configurations available, each name must be a built-in agent type (no handicaps). Planner agents
/// are refused unless `allow_planners` (a hunt through ROS, where the simulator node plays them).
/// @throws InvalidArgument("agents", ...) for an empty panel, a name given twice, an unknown name (listing the
/// valid ones) or a refused planner agent.
std::vector<agents::AgentConfig> resolvePanel(const std::vector<std::string>& names,
                                              const std::vector<agents::AgentConfig>& available,
                                              bool allow_planners = false);

}  // namespace generator
}  // namespace ppp
