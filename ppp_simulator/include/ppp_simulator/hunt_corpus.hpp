#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "ppp_agents/episode_result.hpp"
#include "ppp_agents/prepared_set.hpp"
#include "ppp_core/stop.hpp"
#include "ppp_simulator/experiment_config.hpp"
#include "ppp_simulator/experiment_runner.hpp"

namespace ppp {
namespace simulator {

/// The file an experiment lists its hunted sets' corpus additions in.
constexpr const char* kCorpusLogFile = "corpus.csv";

/// Most failed runs of a PPP a hunt's corpus addition judges its shrink on (the first, in run order).
constexpr int kCorpusJudgedRuns = 3;

/// What became of one failure a hunted set's agent had in an experiment, on the way to the set's corpus.
struct CorpusEntry {
  std::string set;      ///< The hunted set.
  std::string problem;  ///< Its PPP's id.
  std::string agent;    ///< The panel agent that failed it.
  std::string seeds;    ///< The failed runs' seeds judged ("11,42"), as the shrunk PPP's meta shrink_seeds.
  std::string kept;     ///< The failure kept ("loop", "endless loop", "missed_route"); "" when it was not shrunk.
  int descriptors_before = 0;  ///< Descriptors of the hunted PPP.
  int descriptors_after = 0;   ///< And of its shrunk trap.
  std::string trap;     ///< The corpus's file name of the trap: the one written, or the one of the same shape.
  std::string trap_file;  ///< Its path.
  int cells_after = 0;  ///< Its obstacle cells.
  std::uint64_t failing_seed = 0;  ///< The first of `seeds` on which the agent fails the trap.
  bool added = false;   ///< False when the corpus had a trap of the same obstacle shape already.
  std::string note;     ///< Why it was not shrunk ("it does not fail so again", "its planner is gone").
};

/// Whether a set of `config` names a corpus.
bool hasCorpus(const ExperimentConfig& config);

/// @throws IoError, ParseError when a corpus of `config`'s sets is not a directory of PPP files (Corpus), so a bad
/// corpus is refused before any run.
void checkCorpora(const ExperimentConfig& config);

/// Adds the failures of every hunted set of `config` with a corpus: each PPP of the set that an agent of its panel
/// failed in `rows` (results.csv's standing rows; runs lost to the agent link left out), shrunk on the seeds of its
/// first kCorpusJudgedRuns failed runs (shrinkFailure(), its most common diagnosis kept) and added to the corpus
/// once per obstacle shape (Corpus). A built-in agent plays in process, a planner through `planner_rows` (its
/// failures are left out without it, which `log` hears). Corpora named by several sets are one. `log` hears each PPP
/// shrunk.
/// @throws IoError, ParseError, Interrupted when `stop` says stop (every trap added by then is whole).
std::vector<CorpusEntry> addHuntFailuresToCorpora(const ExperimentConfig& config,
                                                  const std::vector<agents::PreparedSet>& sets,
                                                  const std::vector<agents::EpisodeResult>& rows,
                                                  const PlannerRows& planner_rows, const StopCheck& stop = {},
                                                  const std::function<void(const std::string&)>& log = {});

/// The failures `entries` grouped by trap and agent, for the log: a heading ("3 distinct traps in 7 shrunk failures
/// (per agent):"), then distinctFailureLine() per trap with its first entry's PPP and the command that plays it
/// again (`ppp replay` on its first seed for a built-in agent of `config`, launch/check.launch for a planner).
std::vector<std::string> distinctTrapLines(const ExperimentConfig& config, const std::vector<CorpusEntry>& entries);

/// Writes `entries` to `path` as corpus.csv (set, problem, agent, seeds, kept, descriptors_before,
/// descriptors_after, trap, added, note), replacing it whole. @throws IoError.
void writeCorpusLog(const std::string& path, const std::vector<CorpusEntry>& entries);

}  // namespace simulator
}  // namespace ppp
