#pragma once

#include <nlohmann/json.hpp>

#include "ppp_core/barn_metrics.hpp"
#include "ppp_core/evaluation.hpp"

namespace ppp {

/// The evaluation as a JSON object: width, height, valid, turns, advances, turns_plus_advances, obstacles,
/// obstacle_use, visibility{start,goal,centre,top_right,bottom_left}, horizontal_openness, vertical_openness,
/// visibility_function, goal_visibility, visibility_magnitude, difficulty. DPA counts are null when invalid.
nlohmann::json evaluationToJson(const Problem& problem, const Evaluation& evaluation);

/// BARN's metrics as a JSON object: closest_obstacle, visibility, dispersion, characteristic_dimension and
/// tortuosity, each null when the metrics are not valid (no route).
nlohmann::json barnMetricsToJson(const BarnMetrics& metrics);

}  // namespace ppp
