#pragma once

#include <vector>

#include "ppp_core/connectivity.hpp"
#include "ppp_core/motion_options.hpp"
#include "ppp_core/option_spec.hpp"

namespace ppp {

// The rules of the world an agent plays in, shared by everything that plays episodes: the simulator, the hunts
// of the generator and the command line.

/// Largest move budget of an episode.
constexpr int kMaxEpisodeBudget = 1000000;
/// Largest relative budget factor (and soft failure ratio).
constexpr double kMaxBudgetFactor = 1000;

/// When stays or bumps are free, an episode also ends after this many times its budget in actions of any kind.
constexpr int kFreeActionFactor = 4;

/// Which actions use an episode's budget. A plain budget (every action counts) converts from an int.
struct BudgetRule {
  int budget = 300;          ///< Counted actions before the episode fails.
  bool stays_count = true;   ///< A stay uses one of the budget.
  bool bumps_count = true;   ///< A move that bumps uses one of the budget.
  /// A rule of `budget` counted actions.
  BudgetRule(int budget = 300, bool stays_count = true, bool bumps_count = true)  // NOLINT: a plain budget converts
      : budget(budget), stays_count(stays_count), bumps_count(bumps_count) {}
  /// Most actions of any kind: the budget when every action counts, else kFreeActionFactor x the budget.
  long actionLimit() const;
};

/// Rules of one episode besides the agent's own handicaps.
struct EpisodeOptions {
  int budget = 300;          ///< Most actions before the episode fails (when budget_factor is 0).
  double budget_factor = 0;  ///< A relative budget: ceil(factor x the PPP's fewest moves) actions; 0: `budget`.
  int budget_min = 1;        ///< The least budget of an episode (the floor of a relative budget).
  int sensor_range = 2;      ///< Scan radius (2: a 5x5 window).
  Connectivity connectivity = Connectivity::Four;  ///< Move model.
  double soft_failure_ratio = 0;  ///< A passed run longer than ratio x the optimal length is a soft failure; 0: never.
  double robot_radius = 0;   ///< The robot as a disc of this radius in cells (footprint.hpp); <= 0.5: a point.
  bool stays_use_budget = true;  ///< A stay uses one of the budget (false: free, within the action limit).
  bool bumps_use_budget = true;  ///< A bump uses one of the budget (false: free, within the action limit).
  MotionOptions motion;          ///< How the robot moves: the grid (the default) or continuous motion.
  /// The rule of an episode of `budget` (episodeBudget()) under these options.
  BudgetRule budgetRule(int budget) const { return BudgetRule(budget, stays_use_budget, bumps_use_budget); }
  /// @throws InvalidArgument naming the option.
  void validate() const;
};

/// One declaration per episode option (experiment YAML keys, `ppp simulate`/`replay` flags, `ppp generate`
/// flags of the panel fitnesses).
const std::vector<OptionSpec<EpisodeOptions>>& episodeOptionSpecs();

}  // namespace ppp
