#include "ppp_simulator/episode.hpp"

#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/octile.hpp"
#include "ppp_core/option_yaml.hpp"
#include "ppp_core/sensor.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_simulator/episode_result.hpp"

namespace ppp {
namespace simulator {

double pathLength(const EpisodeOutcome& outcome) {
  return outcome.path_length + outcome.diagonal_moves * (kDiagonalCost - 1);
}

std::uint64_t agentSeed(std::uint64_t run_seed) { return deriveSeed(run_seed, {1}); }

std::uint64_t noiseSeed(std::uint64_t run_seed) { return deriveSeed(run_seed, {2}); }

Episode::Episode(const Problem& problem, const Grid& grid, const SensorModel& sensor, std::uint64_t run_seed,
                 int budget, int connectivity, bool record_path, const WindowAtlas* windows)
    : problem_(&problem),
      grid_(&grid),
      sensor_(&sensor),
      windows_(windows),
      noise_seed_(noiseSeed(run_seed)),
      budget_(budget),
      connectivity_(connectivity),
      record_path_(record_path),
      position_(problem.start) {
  if (record_path_) outcome_.path.push_back(position_);
}

Scan Episode::scan() const {
  return Scan(*sensor_, *grid_, position_, problem_->goal, bumped_, outcome_.steps, noise_seed_, windows_);
}

void Episode::apply(agents::Action action) {
  if (done_) return;
  ++outcome_.steps;
  bumped_ = false;
  const bool diagonal = agents::isDiagonal(action);
  if (diagonal && connectivity_ != 8) {
    fail(reason::kInvalidAction);
    return;
  }
  if (action != agents::Action::Stay) {
    const Cell d = agents::offset(action);
    const Cell next{position_.x + d.x, position_.y + d.y};
    // A straight move needs a free target; a diagonal also both cells beside it.
    if (diagonal ? octileMoveAllowed(*grid_, position_, d.x, d.y) : grid_->isFree(next)) {
      position_ = next;
      ++outcome_.path_length;
      if (diagonal) ++outcome_.diagonal_moves;
      if (record_path_) outcome_.path.push_back(position_);
    } else {
      bumped_ = true;
      ++outcome_.bumps;
    }
  }
  if (position_ == problem_->goal) {
    outcome_.passed = true;
    outcome_.reason = reason::kGoalReached;
    done_ = true;
  } else if (outcome_.steps >= budget_) {
    outcome_.reason = reason::kBudgetExhausted;
    done_ = true;
  }
}

void Episode::fail(const char* why) {
  if (done_) return;
  outcome_.passed = false;
  outcome_.reason = why;
  done_ = true;
}

agents::EpisodeInfo episodeInfo(const Problem& problem, const Grid& grid, const agents::AgentConfig& config,
                                std::uint64_t run_seed, int connectivity) {
  agents::EpisodeInfo info;
  info.connectivity = connectivity;
  info.width = grid.width();
  info.height = grid.height();
  info.start = problem.start;
  info.goal = problem.goal;
  info.seed = agentSeed(run_seed);
  info.prior_map = agents::givenPriorMap(config) ? &grid : nullptr;
  return info;
}

EpisodeRunner::EpisodeRunner(const agents::AgentConfig& config, const EpisodeOptions& options)
    : config_((config.validate(), config)),
      options_((options.validate(), options)),
      sensor_(SensorOptions{options.sensor_range, config.sensor_noise}) {}

EpisodeOutcome EpisodeRunner::run(const Problem& problem, const Grid& grid, agents::Agent& agent,
                                  std::uint64_t run_seed, bool record_path, const WindowAtlas* windows) {
  agent.reset(episodeInfo(problem, grid, config_, run_seed, options_.connectivity));
  Episode episode(problem, grid, sensor_, run_seed, options_.budget, options_.connectivity, record_path, windows);
  while (!episode.done()) episode.apply(agent.act(episode.scan()));
  return episode.outcome();
}

EpisodeOutcome recordEpisode(const Problem& problem, const Grid& grid, const agents::AgentConfig& config,
                             const EpisodeOptions& options, std::uint64_t run_seed) {
  EpisodeRunner runner(config, options);
  auto agent = agents::makeAgent(config);
  return runner.run(problem, grid, *agent, run_seed, true);
}

}  // namespace simulator
}  // namespace ppp
