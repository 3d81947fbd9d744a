#include "ppp_core/episode_options.hpp"

#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/footprint.hpp"
#include "ppp_core/option_yaml.hpp"
#include "ppp_core/sensor.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {

long BudgetRule::actionLimit() const {
  return stays_count && bumps_count ? budget : static_cast<long>(kFreeActionFactor) * budget;
}

void EpisodeOptions::validate() const {
  checkOptionRanges(episodeOptionSpecs(), *this);
  if (soft_failure_ratio != 0 && soft_failure_ratio < 1) {
    throw InvalidArgument("soft_failure_ratio", "expected 0 (no soft failures) or a ratio of at least 1, got " +
                                                    formatShortest(soft_failure_ratio));
  }
}

const std::vector<OptionSpec<EpisodeOptions>>& episodeOptionSpecs() {
  using E = EpisodeOptions;
  static const std::vector<OptionSpec<E>> specs = [] {
    std::vector<OptionSpec<E>> list = {
      declareOption("budget", "moves per episode before it fails", +[](E& e) -> int& { return e.budget; },
                    Bounds{1, kMaxEpisodeBudget}),
      declareOption("budget_factor",
                    "relative budget: each episode gets ceil(K x its PPP's fewest moves) moves (0: the absolute budget)",
                    +[](E& e) -> double& { return e.budget_factor; }, Bounds{0, kMaxBudgetFactor})
          .excluding("budget"),
      declareOption("budget_min", "the least budget of an episode, in moves (the floor of a relative budget)", +[](E& e) -> int& { return e.budget_min; },
                    Bounds{1, kMaxEpisodeBudget}),
      declareOption("sensor_range", "scan radius in cells (2: a 5x5 window)",
                    +[](E& e) -> int& { return e.sensor_range; }, Bounds{1, kMaxSensorRange}),
      declareOption("connectivity", "move model (agents other than astar move 4-connected either way)",
                    +[](E& e) -> Connectivity& { return e.connectivity; }, Bounds{4, 8})
          .withChoices("connectivity", {{"4", "stay and the four straight moves"},
                                        {"8", "also the four diagonals, never cutting a corner"}}),
      declareOption("soft_failure_ratio",
                    "a passed run whose path is longer than R x the optimal length is a soft failure (0: none)",
                    +[](E& e) -> double& { return e.soft_failure_ratio; }, Bounds{0, kMaxBudgetFactor}),
      declareOption("robot_radius",
                    "the robot as a disc of this radius in cells; a move that would put it over an obstacle or off "
                    "the map bumps (0: a point; in continuous motion a disc of radius x resolution metres)",
                    +[](E& e) -> double& { return e.robot_radius; }, Bounds{0, kMaxRobotRadius}),
      declareOption("stays_use_budget",
                    "a stay uses one move of the budget (false: stays are free; an episode then also ends after " +
                        std::to_string(kFreeActionFactor) + " x budget actions, as action_limit)",
                    +[](E& e) -> bool& { return e.stays_use_budget; }),
      declareOption("bumps_use_budget",
                    "a move into an obstacle or off the map uses one move of the budget (false: bumps are free; "
                    "an episode then also ends after " +
                        std::to_string(kFreeActionFactor) + " x budget actions, as action_limit)",
                    +[](E& e) -> bool& { return e.bumps_use_budget; }),
    };
    for (const OptionSpec<E>& spec : nestedOptions(motionOptionSpecs(), +[](E& e) -> MotionOptions& {
           return e.motion;
         })) {
      list.push_back(spec);
    }
    return list;
  }();
  return specs;
}

}  // namespace ppp
