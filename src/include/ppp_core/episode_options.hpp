#pragma once

#include <vector>

#include "ppp_core/connectivity.hpp"
#include "ppp_core/option_spec.hpp"

namespace ppp {

// The rules of the world an agent plays in, shared by everything that plays episodes: the simulator, the hunts
// of the generator and the command line.

/// Largest move budget of an episode.
constexpr int kMaxEpisodeBudget = 1000000;

/// Rules of one episode besides the agent's own handicaps.
struct EpisodeOptions {
  int budget = 300;       ///< Most actions before the episode fails.
  int sensor_range = 2;   ///< Scan radius (2: a 5x5 window).
  Connectivity connectivity = Connectivity::Four;  ///< Move model.
  /// @throws InvalidArgument("budget", "sensor_range" or "connectivity", ...).
  void validate() const;
};

/// One declaration per episode option (experiment YAML keys, `ppp simulate`/`replay` flags, `ppp generate`
/// flags of the failure fitness).
const std::vector<OptionSpec<EpisodeOptions>>& episodeOptionSpecs();

}  // namespace ppp
