#pragma once

#include <array>
#include <string>
#include <vector>

#include "ppp_core/dpa.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/visibility.hpp"

namespace ppp {

/// Weights of the difficulty score (docs/reference/evaluation.md); the defaults are the dissertation's.
struct DifficultyWeights {
  double start = 1.5;                ///< Weight of visibility from the start.
  double centre = 1.0;               ///< Weight of visibility from the centre.
  double top_right = 1.0;            ///< Weight of visibility from the top-right corner.
  double bottom_left = 1.0;          ///< Weight of visibility from the bottom-left corner.
  double goal = 2.5;                 ///< Weight of visibility from the goal.
  double unused_obstacles = 2.0;     ///< Weight of (1 - ObstacleUse).
  double horizontal_openness = 2.0;  ///< Weight of AvgHorizontalOpenness.
  double vertical_openness = 2.0;    ///< Weight of AvgVerticalOpenness.
  double one_turn_penalty = 2.0;     ///< Added when the optimal route needs exactly one turn.
  /// Checks every weight is a finite number. @throws InvalidArgument naming the weight.
  void validate() const;
};

/// Fraction of the grid visible from each of the five viewpoints.
struct Visibilities {
  double start = 0;        ///< From the start cell.
  double goal = 0;         ///< From the goal cell.
  double centre = 0;       ///< From the centre cell (width/2, height/2).
  double top_right = 0;    ///< From (width-1, 0).
  double bottom_left = 0;  ///< From (0, height-1).
};

/// Every measure of one PPP (docs/reference/evaluation.md): the DPA, visibility, openness, difficulty.
struct Evaluation {
  bool valid = false;               ///< Goal reachable from start.
  int turns = -1;                   ///< Fewest turns (-1 when invalid).
  int advances = -1;                ///< Fewest advances (-1 when invalid).
  int turns_plus_advances = -1;     ///< Fewest turns + advances (-1 when invalid).
  int obstacles = 0;                ///< Descriptors in the chromosome.
  double obstacle_use = 0;          ///< obstacles / max_obstacles (0 when the budget is 0).
  Visibilities visibility;          ///< The five viewpoint visibilities.
  double horizontal_openness = 0;   ///< AvgHorizontalOpenness.
  double vertical_openness = 0;     ///< AvgVerticalOpenness.
  double visibility_function = 0;   ///< Weighted sum of the five visibilities.
  double goal_visibility = 0;       ///< The dissertation's first variant: goal visibility alone.
  double visibility_magnitude = 0;  ///< Its second variant: Euclidean norm of the five visibilities.
  double difficulty = 0;            ///< The difficulty score (lower is harder).
};

/// The viewpoints used for visibility, in the order start, goal, centre, top-right, bottom-left.
std::array<Cell, 5> viewpoints(const Problem& problem);

/// Computes every measure; holds solver buffers, so reuse one evaluator for many problems.
class Evaluator {
 public:
  /// An evaluator using the given difficulty weights. @throws InvalidArgument for a non-finite weight.
  explicit Evaluator(const DifficultyWeights& weights = {});
  /// Evaluates a problem whose grid has already been decoded.
  Evaluation evaluate(const Problem& problem, const Grid& grid);
  /// Decodes and evaluates a problem.
  Evaluation evaluate(const Problem& problem);
  /// Evaluates with a DPA result the caller already has for this grid (saves solving it again).
  Evaluation evaluate(const Problem& problem, const Grid& grid, const DpaResult& dpa);

 private:
  DifficultyWeights weights_;
  DpaSolver dpa_;
  VisibilitySolver visibility_;
};

/// Names of the taxonomic characters (docs/reference/evaluation.md), in characterVector() order.
const std::vector<std::string>& characterNames();
/// Wei's four characters (turns, advances, turns_plus_advances, obstacles): the first four names.
constexpr std::size_t kWeiCharacterCount = 4;
/// The full character vector of one evaluation.
std::vector<double> characterVector(const Evaluation& evaluation);

}  // namespace ppp
