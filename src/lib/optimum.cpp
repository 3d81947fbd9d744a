#include "ppp_core/optimum.hpp"

#include <algorithm>
#include <cmath>

#include "ppp_core/footprint.hpp"
#include "ppp_core/octile.hpp"
#include "ppp_core/reachability.hpp"

namespace ppp {

Optimum optimumOf(const Problem& problem, const Grid& grid, Connectivity connectivity) {
  Optimum optimum;
  optimum.moves = fewestMoves(grid, problem.start, problem.goal, connectivity);
  if (optimum.moves < 0) return optimum;
  optimum.length = connectivity == Connectivity::Eight ? shortestOctileRoute(grid, problem.start, problem.goal).length
                                                       : static_cast<double>(optimum.moves);
  return optimum;
}

int episodeBudget(const EpisodeOptions& options, int optimal_moves) {
  if (options.budget_factor == 0) return std::max(options.budget, options.budget_min);
  // 1.1 x 40 is 44.000000000000007 in doubles: a product within 1e-9 of a whole number is that number.
  const double relative = std::ceil(options.budget_factor * std::max(optimal_moves, 0) - 1e-9);
  return static_cast<int>(std::clamp(relative, static_cast<double>(options.budget_min),
                                     static_cast<double>(kMaxEpisodeBudget)));
}

int episodeBudget(const EpisodeOptions& options, const Problem& problem, const Grid& grid) {
  if (options.budget_factor == 0) return episodeBudget(options, 0);
  Grid space;
  return episodeBudget(options, optimumOf(problem, motionGrid(grid, options.robot_radius, &space), options.connectivity).moves);
}

double runRegret(bool passed, int steps, int budget, int optimal_moves) {
  const double optimal = std::max(optimal_moves, 1);
  return ((passed ? steps : budget) - optimal) / optimal;
}

bool isSoftFailure(bool passed, double path_length, double optimal_length, double ratio) {
  return ratio > 0 && passed && path_length > ratio * optimal_length;
}

}  // namespace ppp
