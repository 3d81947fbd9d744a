#pragma once

#include <vector>

#include "ppp_core/connectivity.hpp"
#include "ppp_core/option_spec.hpp"

namespace ppp {

// The rules of the world an agent plays in, shared by everything that plays episodes: the simulator, the hunts
// of the generator and the command line.

/// Largest move budget of an episode.
constexpr int kMaxEpisodeBudget = 1000000;
/// Largest relative budget factor (and soft failure ratio).
constexpr double kMaxBudgetFactor = 1000;

/// Rules of one episode besides the agent's own handicaps.
struct EpisodeOptions {
  int budget = 300;          ///< Most actions before the episode fails (when budget_factor is 0).
  double budget_factor = 0;  ///< A relative budget: ceil(factor x the PPP's fewest moves) actions; 0: `budget`.
  int budget_min = 1;        ///< The least budget of an episode (the floor of a relative budget).
  int sensor_range = 2;      ///< Scan radius (2: a 5x5 window).
  Connectivity connectivity = Connectivity::Four;  ///< Move model.
  double soft_failure_ratio = 0;  ///< A passed run longer than ratio x the optimal length is a soft failure; 0: never.
  double robot_radius = 0;   ///< The robot as a disc of this radius in cells (footprint.hpp); <= 0.5: a point.
  /// @throws InvalidArgument naming the option.
  void validate() const;
};

/// One declaration per episode option (experiment YAML keys, `ppp simulate`/`replay` flags, `ppp generate`
/// flags of the panel fitnesses).
const std::vector<OptionSpec<EpisodeOptions>>& episodeOptionSpecs();

}  // namespace ppp
