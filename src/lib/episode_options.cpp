#include "ppp_core/episode_options.hpp"

#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/option_yaml.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {

void EpisodeOptions::validate() const { checkOptionRanges(episodeOptionSpecs(), *this); }

const std::vector<OptionSpec<EpisodeOptions>>& episodeOptionSpecs() {
  using E = EpisodeOptions;
  static const std::vector<OptionSpec<E>> specs = {
      declareOption("budget", "moves per episode before it fails", +[](E& e) -> int& { return e.budget; },
                    Bounds{1, kMaxEpisodeBudget}),
      declareOption("sensor_range", "scan radius in cells (2: a 5x5 window)",
                    +[](E& e) -> int& { return e.sensor_range; }, Bounds{1, kMaxSensorRange}),
      declareOption("connectivity", "move model (agents other than astar move 4-connected either way)",
                    +[](E& e) -> Connectivity& { return e.connectivity; }, Bounds{4, 8})
          .withChoices("connectivity", {{"4", "stay and the four straight moves"},
                                        {"8", "also the four diagonals, never cutting a corner"}}),
  };
  return specs;
}

}  // namespace ppp
