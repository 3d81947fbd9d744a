#include "ppp_core/random_problem.hpp"

#include <algorithm>
#include <iterator>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/reachability.hpp"

namespace ppp {

std::string shapeListText(std::vector<Shape> shapes) {
  std::string text;
  for (const Shape shape : shapes) text += (text.empty() ? "" : ",") + std::string(shapeName(shape));
  return text;
}

std::string shapeListProblem(const std::string& text, std::vector<Shape>* shapes) {
  shapes->clear();
  std::string item;
  for (const char c : text + ",") {
    if (c != ',') {
      if (c != ' ') item += c;
      continue;
    }
    Shape shape;
    if (!parseShape(item, &shape)) {
      return "unknown shape '" + item + "' in '" + text + "'; expected keywords among hbar, vbar, diag_down, "
             "diag_up, block separated by commas";
    }
    shapes->push_back(shape);
    item.clear();
  }
  return "";
}

Obstacle randomObstacle(Rng& rng, int width, int height, const RandomObstacleOptions& options) {
  const int bar = options.max_bar_length > 0 ? options.max_bar_length : std::max(1, std::max(width, height) / 2);
  const int side = options.max_block_side > 0 ? options.max_block_side : std::max(1, std::min(width, height) / 4);
  Obstacle o;
  o.shape = options.shapes[rng.below(options.shapes.size())];
  o.x = static_cast<int>(rng.below(static_cast<std::uint64_t>(width)));
  o.y = static_cast<int>(rng.below(static_cast<std::uint64_t>(height)));
  if (o.shape == Shape::Block) {
    o.length = static_cast<int>(rng.uniformInt(1, std::min(side, width)));
    o.height = static_cast<int>(rng.uniformInt(1, std::min(side, height)));
  } else {
    const int longest = std::min(bar, std::max(width, height));
    o.length = static_cast<int>(rng.uniformInt(std::min(options.min_bar_length, longest), longest));
    o.height = 1;
  }
  return o;
}

Problem randomProblem(Rng& rng, const Problem& shape, int obstacle_count, const RandomObstacleOptions& options,
                      int max_attempts) {
  Problem problem = shape;
  problem.obstacles.clear();
  validateProblem(problem);
  if (obstacle_count < 0 || obstacle_count > problem.max_obstacles) {
    throw InvalidArgument("obstacles", "expected a count in [0, " + std::to_string(problem.max_obstacles) +
                                           "], got " + std::to_string(obstacle_count));
  }
  for (int attempt = 0; attempt < max_attempts; ++attempt) {
    problem.obstacles.clear();
    for (int i = 0; i < obstacle_count; ++i) {
      problem.obstacles.push_back(randomObstacle(rng, problem.width, problem.height, options));
    }
    if (isReachable(decodeGrid(problem), problem.start, problem.goal)) return problem;
  }
  throw InvalidArgument("obstacles", "no solvable problem with " + std::to_string(obstacle_count) +
                                         " random obstacles in " + std::to_string(max_attempts) + " attempts");
}

}  // namespace ppp
