#pragma once

#include <string>
#include <vector>

#include "ppp_core/problem.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {

/// Limits on the descriptors drawn at random (by `ppp random` and by the generator's mutation).
struct RandomObstacleOptions {
  int max_bar_length = 0;  ///< Longest bar drawn; 0 means half the longer grid side.
  int max_block_side = 0;  ///< Longest block side drawn; 0 means a quarter of the shorter grid side.
  int min_bar_length = 1;  ///< Shortest bar drawn (capped at the longest).
  /// The shapes drawn, each entry equally likely (a shape listed twice is drawn twice as often); not empty.
  std::vector<Shape> shapes{std::begin(kAllShapes), std::end(kAllShapes)};
};

/// A shape mix as options write it: shape keywords separated by commas ("hbar,vbar,block").
std::string shapeListText(std::vector<Shape> shapes);

/// Parses a shape mix into `shapes`; returns what is wrong ("" when nothing is).
std::string shapeListProblem(const std::string& text, std::vector<Shape>* shapes);

/// A descriptor with a uniformly chosen shape, an anchor anywhere on the grid and a size within the limits.
Obstacle randomObstacle(Rng& rng, int width, int height, const RandomObstacleOptions& options = {});

/// Draws problems with `obstacle_count` random descriptors until one is valid (goal reachable).
/// The start is top-left and the goal bottom-right unless the template problem sets them.
/// @throws InvalidArgument for a bad template or when `max_attempts` draws are all unsolvable.
Problem randomProblem(Rng& rng, const Problem& shape, int obstacle_count, const RandomObstacleOptions& options = {},
                      int max_attempts = 10000);

}  // namespace ppp
