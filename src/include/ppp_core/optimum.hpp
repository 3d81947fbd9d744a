#pragma once

#include "ppp_core/connectivity.hpp"
#include "ppp_core/episode_options.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/problem.hpp"

namespace ppp {

// The yardstick of a run: what the best route of a PPP costs under the episode's rules, and the measures taken
// against it (relative budgets, regret, soft failures: docs/how-to/graded-objectives.md).

/// The best a run can do on one PPP.
struct Optimum {
  int moves = -1;      ///< Fewest moves from start to goal under the move model (-1: the goal cannot be reached).
  double length = -1;  ///< Shortest length: the fewest moves under connectivity 4, the octile length under 8.
};

/// The optimum of `problem` on `grid` (its decoded grid, or the robot's configuration space) under the move model
/// `connectivity`.
Optimum optimumOf(const Problem& problem, const Grid& grid, Connectivity connectivity);

/// The move budget of an episode on a PPP whose optimum takes `optimal_moves`: the absolute `budget`, or under a
/// `budget_factor` K, ceil(K x optimal_moves); either at least `budget_min` (and at most kMaxEpisodeBudget).
int episodeBudget(const EpisodeOptions& options, int optimal_moves);

/// episodeBudget() of `problem` (decoded as `grid`), finding its optimum (in the robot's configuration space) only
/// for a relative budget.
int episodeBudget(const EpisodeOptions& options, const Problem& problem, const Grid& grid);

/// A run's regret: (moves used - optimal moves) / optimal moves, where a failed run used its whole `budget`
/// (moves are actions: stays and bumps count, as they do against the budget).
double runRegret(bool passed, int steps, int budget, int optimal_moves);

/// True when a passed run's path is longer than `ratio` x the optimal length (never when `ratio` is 0).
bool isSoftFailure(bool passed, double path_length, double optimal_length, double ratio);

}  // namespace ppp
