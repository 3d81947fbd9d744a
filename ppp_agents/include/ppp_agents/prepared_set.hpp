#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ppp_agents/episode_result.hpp"
#include "ppp_core/episode.hpp"
#include "ppp_core/episode_options.hpp"
#include "ppp_core/failure_signature.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/problem_set.hpp"
#include "ppp_core/window_atlas.hpp"

namespace ppp {
namespace agents {

/// A PPP set ready to run under one episode's rules: its PPPs, decoded grids, optima and budgets.
struct PreparedSet {
  std::string name;              ///< Set name.
  std::string directory;         ///< The set's directory (PPP files, set.csv, trees, any archive).
  ProblemSet set;                ///< The PPPs and their evaluations.
  EpisodeOptions episode;        ///< The rules it is played under.
  std::vector<Grid> grids;       ///< Decoded grid of each PPP.
  std::vector<Grid> spaces;      ///< The robot's configuration space on each PPP (empty for a point robot).
  std::vector<double> optimal;   ///< Optimal length of each PPP: fewest moves (connectivity 4), octile length (8).
  std::vector<int> moves;        ///< Fewest moves of each PPP under the move model.
  std::vector<int> budgets;      ///< Move budget of each PPP's episodes (episodeBudget()).
  /// Each PPP's WindowAtlas at the experiment's sensor range, when it fits kMaxWindowAtlasBytes.
  std::vector<std::optional<WindowAtlas>> windows;
  /// What each PPP's failure signatures read (distances on the robot's motion grid, obstacle sides).
  std::vector<SignatureMap> signature_maps;
};

/// The most actions any episode of `sets` may take (its budget, or its action limit when stays or bumps are free).
int largestActionLimit(const std::vector<PreparedSet>& sets);

/// The grid the robot moves on in PPP `problem` of `set`: its configuration space, or nullptr for a point robot
/// (which moves on the PPP's grid).
inline const Grid* motionOf(const PreparedSet& set, int problem) {
  return set.spaces.empty() ? nullptr : &set.spaces[problem];
}

/// PPP `problem`'s WindowAtlas in `set`, or nullptr when it has none.
inline const WindowAtlas* windowsOf(const PreparedSet& set, int problem) {
  const std::optional<WindowAtlas>& windows = set.windows[problem];
  return windows ? &*windows : nullptr;
}

/// The results.csv row of one run of `agent` on PPP `problem` of `set` (a soft failure under its rules), with
/// its diagnosis (diagnoseRun() of the outcome's cells, the agent's decision `states` when it reported them, and
/// the `reported_kind` it gave for its own ending) and its failure signature.
EpisodeResult episodeResult(const PreparedSet& set, int problem, const std::string& agent, int run,
                            std::uint64_t seed, const EpisodeOutcome& outcome,
                            const std::vector<std::uint64_t>& states = {}, const char* reported_kind = nullptr);

/// Sets `d` as the diagnosis of `result`, a run on PPP `problem` of `set` whose robot stood on `cells`, with the
/// failure signature it makes there.
void setDiagnosisAndSignature(const PreparedSet& set, int problem, const Diagnosis& d, const std::vector<Cell>& cells,
                              EpisodeResult* result);

/// prepareSet() of a set holding `problem` alone, as PPP `id` of set `name` (one PPP replayed or judged).
/// @throws InvalidArgument as prepareSet().
PreparedSet prepareSingle(const std::string& name, const std::string& id, const Problem& problem,
                          const EpisodeOptions& episode);

/// A set ready to play under `episode`'s rules: its grids, optima (optimumOf()), budgets, window atlases at
/// the sensor range and signature maps.
/// @throws InvalidArgument naming "sets" for a PPP unsolvable for the robot (4-connected, with its body).
PreparedSet prepareSet(const std::string& name, ProblemSet set, const EpisodeOptions& episode);

}  // namespace agents
}  // namespace ppp
