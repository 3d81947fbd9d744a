#include "ppp_core/evaluation_json.hpp"

namespace ppp {

nlohmann::json evaluationToJson(const Problem& problem, const Evaluation& e) {
  auto count = [&](int value) { return e.valid ? nlohmann::json(value) : nlohmann::json(nullptr); };
  nlohmann::json j;
  j["width"] = problem.width;
  j["height"] = problem.height;
  j["valid"] = e.valid;
  j["turns"] = count(e.turns);
  j["advances"] = count(e.advances);
  j["turns_plus_advances"] = count(e.turns_plus_advances);
  j["obstacles"] = e.obstacles;
  j["obstacle_use"] = e.obstacle_use;
  j["visibility"] = {{"start", e.visibility.start},
                     {"goal", e.visibility.goal},
                     {"centre", e.visibility.centre},
                     {"top_right", e.visibility.top_right},
                     {"bottom_left", e.visibility.bottom_left}};
  j["horizontal_openness"] = e.horizontal_openness;
  j["vertical_openness"] = e.vertical_openness;
  j["visibility_function"] = e.visibility_function;
  j["goal_visibility"] = e.goal_visibility;
  j["visibility_magnitude"] = e.visibility_magnitude;
  j["difficulty"] = e.difficulty;
  return j;
}

nlohmann::json barnMetricsToJson(const BarnMetrics& m) {
  auto value = [&](double v) { return m.valid ? nlohmann::json(v) : nlohmann::json(nullptr); };
  return {{"closest_obstacle", value(m.closest_obstacle)},
          {"visibility", value(m.visibility)},
          {"dispersion", value(m.dispersion)},
          {"characteristic_dimension", value(m.characteristic_dimension)},
          {"tortuosity", value(m.tortuosity)}};
}

}  // namespace ppp
