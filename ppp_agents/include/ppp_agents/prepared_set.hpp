#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ppp_agents/episode_result.hpp"
#include "ppp_core/episode.hpp"
#include "ppp_core/episode_options.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/problem_set.hpp"
#include "ppp_core/window_atlas.hpp"

namespace ppp {
namespace agents {

/// A PPP set ready to run: its PPPs, decoded grids and optimal lengths.
struct PreparedSet {
  std::string name;              ///< Set name.
  std::string directory;         ///< The set's directory (PPP files, set.csv, trees, any archive).
  ProblemSet set;     ///< The PPPs and their evaluations.
  std::vector<Grid> grids;       ///< Decoded grid of each PPP.
  std::vector<double> optimal;   ///< Optimal length of each PPP: fewest moves (connectivity 4), octile length (8).
  /// Each PPP's WindowAtlas at the experiment's sensor range, when it fits kMaxWindowAtlasBytes.
  std::vector<std::optional<WindowAtlas>> windows;
};

/// PPP `problem`'s WindowAtlas in `set`, or nullptr when it has none.
inline const WindowAtlas* windowsOf(const PreparedSet& set, int problem) {
  const std::optional<WindowAtlas>& windows = set.windows[problem];
  return windows ? &*windows : nullptr;
}

/// The results.csv row of one run of `agent` on PPP `problem` of `set`.
EpisodeResult episodeResult(const PreparedSet& set, int problem, const std::string& agent, int run,
                            std::uint64_t seed, const EpisodeOutcome& outcome);

/// A set ready to play under `episode`'s rules: its grids, optimal lengths (the fewest moves, or the octile
/// length under connectivity 8) and window atlases at the sensor range.
/// @throws InvalidArgument naming "sets" for an unsolvable PPP.
PreparedSet prepareSet(const std::string& name, ProblemSet set, const EpisodeOptions& episode);

}  // namespace agents
}  // namespace ppp
