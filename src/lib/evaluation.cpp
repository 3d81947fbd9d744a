#include "ppp_core/evaluation.hpp"

#include <cmath>

#include "ppp_core/error.hpp"
#include "ppp_core/openness.hpp"

namespace ppp {

void DifficultyWeights::validate() const {
  const std::pair<const char*, double> weights[] = {
      {"start", start},
      {"centre", centre},
      {"top_right", top_right},
      {"bottom_left", bottom_left},
      {"goal", goal},
      {"unused_obstacles", unused_obstacles},
      {"horizontal_openness", horizontal_openness},
      {"vertical_openness", vertical_openness},
      {"one_turn_penalty", one_turn_penalty},
  };
  for (const auto& w : weights) {
    if (!std::isfinite(w.second)) throw InvalidArgument(std::string("weights.") + w.first, "must be a finite number");
  }
}

std::array<Cell, 5> viewpoints(const Problem& p) {
  return {p.start, p.goal, Cell{p.width / 2, p.height / 2}, Cell{p.width - 1, 0}, Cell{0, p.height - 1}};
}

Evaluator::Evaluator(const DifficultyWeights& weights) : weights_(weights) { weights_.validate(); }

Evaluation Evaluator::evaluate(const Problem& problem) { return evaluate(problem, decodeGrid(problem)); }

Evaluation Evaluator::evaluate(const Problem& problem, const Grid& grid) {
  return evaluate(problem, grid, dpa_.solve(grid, problem.start, problem.goal));
}

Evaluation Evaluator::evaluate(const Problem& problem, const Grid& grid, const DpaResult& dpa) {
  Evaluation e;
  e.valid = dpa.reachable;
  e.turns = dpa.turns;
  e.advances = dpa.advances;
  e.turns_plus_advances = dpa.turns_plus_advances;
  e.obstacles = static_cast<int>(problem.obstacles.size());
  e.obstacle_use = problem.max_obstacles > 0 ? static_cast<double>(e.obstacles) / problem.max_obstacles : 0.0;
  const auto points = viewpoints(problem);
  double* targets[5] = {&e.visibility.start, &e.visibility.goal, &e.visibility.centre, &e.visibility.top_right,
                        &e.visibility.bottom_left};
  for (int i = 0; i < 5; ++i) {
    *targets[i] = static_cast<double>(visibility_.solve(grid, points[i])) / grid.size();
  }
  e.horizontal_openness = horizontalOpenness(grid);
  e.vertical_openness = verticalOpenness(grid);
  const Visibilities& v = e.visibility;
  e.visibility_function = weights_.start * v.start + weights_.centre * v.centre + weights_.top_right * v.top_right +
                          weights_.bottom_left * v.bottom_left + weights_.goal * v.goal;
  e.goal_visibility = v.goal;
  e.visibility_magnitude = std::sqrt(v.start * v.start + v.goal * v.goal + v.centre * v.centre +
                                     v.top_right * v.top_right + v.bottom_left * v.bottom_left);
  e.difficulty = e.visibility_function + weights_.unused_obstacles * (1.0 - e.obstacle_use) +
                 weights_.horizontal_openness * e.horizontal_openness +
                 weights_.vertical_openness * e.vertical_openness + (e.turns == 1 ? weights_.one_turn_penalty : 0.0);
  return e;
}

const std::vector<std::string>& characterNames() {
  static const std::vector<std::string> names = {
      "turns",          "advances",        "turns_plus_advances",  "obstacles",
      "visibility_start", "visibility_goal", "visibility_centre",  "visibility_top_right",
      "visibility_bottom_left", "obstacle_use", "horizontal_openness", "vertical_openness",
      "one_turn",       "difficulty",
  };
  return names;
}

std::vector<double> characterVector(const Evaluation& e) {
  return {static_cast<double>(e.turns),
          static_cast<double>(e.advances),
          static_cast<double>(e.turns_plus_advances),
          static_cast<double>(e.obstacles),
          e.visibility.start,
          e.visibility.goal,
          e.visibility.centre,
          e.visibility.top_right,
          e.visibility.bottom_left,
          e.obstacle_use,
          e.horizontal_openness,
          e.vertical_openness,
          e.turns == 1 ? 1.0 : 0.0,
          e.difficulty};
}

}  // namespace ppp
