#include "ppp_simulator/episode.hpp"

#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_simulator/episode_result.hpp"

namespace ppp {
namespace simulator {

namespace {

constexpr int kMaxBudget = 1000000;

}  // namespace

void EpisodeOptions::validate() const {
  if (budget < 1 || budget > kMaxBudget) {
    throw InvalidArgument("budget", "expected a move budget in [1, " + std::to_string(kMaxBudget) + "], got " +
                                        std::to_string(budget));
  }
  SensorOptions{sensor_range, 0.0}.validate();
}

std::uint64_t agentSeed(std::uint64_t run_seed) { return deriveSeed(run_seed, {1}); }

std::uint64_t noiseSeed(std::uint64_t run_seed) { return deriveSeed(run_seed, {2}); }

EpisodeRunner::EpisodeRunner(const agents::AgentConfig& config, const EpisodeOptions& options)
    : config_((config.validate(), config)),
      options_((options.validate(), options)),
      sensor_(SensorOptions{options.sensor_range, config.sensor_noise}),
      prior_map_(config.type == "astar") {}

EpisodeOutcome EpisodeRunner::run(const Problem& problem, const Grid& grid, agents::Agent& agent,
                                  std::uint64_t run_seed, bool record_path) {
  agents::EpisodeInfo info;
  info.width = grid.width();
  info.height = grid.height();
  info.start = problem.start;
  info.goal = problem.goal;
  info.seed = agentSeed(run_seed);
  info.prior_map = prior_map_ ? &grid : nullptr;
  agent.reset(info);
  const std::uint64_t noise = noiseSeed(run_seed);
  EpisodeOutcome outcome;
  Cell position = problem.start;
  bool bumped = false;
  if (record_path) outcome.path.push_back(position);
  while (outcome.steps < options_.budget) {
    const Scan scan(sensor_, grid, position, problem.goal, bumped, outcome.steps, noise);
    const agents::Action action = agent.act(scan);
    ++outcome.steps;
    bumped = false;
    if (action != agents::Action::Stay) {
      const Cell next = agents::target(position, action);
      if (grid.isFree(next)) {
        position = next;
        ++outcome.path_length;
        if (record_path) outcome.path.push_back(position);
      } else {
        bumped = true;
        ++outcome.bumps;
      }
    }
    if (position == problem.goal) {
      outcome.passed = true;
      outcome.reason = reason::kGoalReached;
      return outcome;
    }
  }
  outcome.reason = reason::kBudgetExhausted;
  return outcome;
}

}  // namespace simulator
}  // namespace ppp
