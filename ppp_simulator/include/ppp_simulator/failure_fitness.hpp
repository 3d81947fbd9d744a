#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_generator/fitness.hpp"
#include "ppp_generator/generator_options.hpp"
#include "ppp_simulator/episode.hpp"

namespace ppp {
namespace simulator {

/// PPPs scored per call of the failure fitness's batch scorer (and matings per round of a hunt).
constexpr int kFailureBatchSize = 16;

/// The agents and rules of a failure fitness (SPEC 6b).
struct FailurePanel {
  std::vector<agents::AgentConfig> agents;  ///< The panel, each run `runs_per_eval` times per PPP.
  EpisodeOptions episode;                   ///< Budget and sensor range of the episodes.
  int runs_per_eval = 20;                   ///< Episodes per agent per PPP.
  std::uint64_t seed = 1;                   ///< The generator seed the run seeds derive from.
  int threads = 0;                          ///< Worker threads; 0 = every core.
};

/// The seed of run `run` of panel agent `agent` on a PPP whose grid hashes to `grid_hash`: the same PPP is
/// always judged on the same runs (common random numbers), whatever the batch, thread or mating it came in.
std::uint64_t failureRunSeed(std::uint64_t generator_seed, std::uint64_t grid_hash, const std::string& agent,
                             int run);

/// One PPP's failure figures.
struct FailureEstimate {
  double failure_rate = 0;  ///< Mean over the panel of each agent's share of failed runs.
  double budget_used = 0;   ///< Mean share of the budget the panel's runs used.
};

/// Plays every panel agent runs_per_eval times on each PPP (in parallel over PPPs and agents) and returns
/// the figures in input order. @throws InvalidArgument for a planner agent (those run only through ROS).
std::vector<FailureEstimate> estimateFailures(const FailurePanel& panel, const std::vector<const Problem*>& problems,
                                              const std::vector<const Grid*>& grids);

/// The failure fitness: value = the failure rate, maximised; score = value + 0.001 × budget_used, so that
/// among PPPs the panel passes equally often, the one that keeps it busy longest wins (a gradient for the
/// search before the first failure is found). Scores kFailureBatchSize PPPs per call.
/// @throws InvalidArgument("agents", ...) for an empty panel or a planner agent.
generator::Fitness makeFailureFitness(const FailurePanel& panel);

/// The fitness of a set's generator options: makeFitness(options.fitness), or for `failure` the failure
/// fitness of the panel options.agents looked up in `available` (see resolvePanel), played with `episode`'s
/// rules on `threads` threads (0: every core). @throws InvalidArgument naming the option.
generator::Fitness fitnessFor(const generator::GeneratorOptions& options,
                              const std::vector<agents::AgentConfig>& available, const EpisodeOptions& episode,
                              int threads);

/// Looks up the panel `names` among `available` configurations (an experiment's agents or an agents file);
/// with no configurations available, each name must be a built-in agent type (no handicaps).
/// @throws InvalidArgument("agents", ...) naming an unknown name (listing the valid ones) or a planner agent.
std::vector<agents::AgentConfig> resolvePanel(const std::vector<std::string>& names,
                                              const std::vector<agents::AgentConfig>& available);

}  // namespace simulator
}  // namespace ppp
