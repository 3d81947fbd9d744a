#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "ppp_core/option_spec.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/stop.hpp"
#include "ppp_simulator/failure_shrink.hpp"

namespace ppp {
namespace simulator {

/// Runs `ppp check` plays on a PPP without recorded seeds, unless told otherwise.
constexpr int kDefaultCheckRuns = 3;

/// One PPP of a corpus, as `ppp check` plays it.
struct CorpusCase {
  std::string name;                  ///< Its name in the corpus: the file's name without the extension.
  std::string file;                  ///< Its file.
  Problem problem;                   ///< The PPP.
  std::vector<std::uint64_t> seeds;  ///< The run seeds it is played on.
  bool recorded = false;             ///< The seeds are its own (meta shrink_seeds), not derived from a given seed.
};

/// The PPPs of `corpus` (a directory, as generator::problemSetFiles() lists it, or one PPP file) in order, each
/// with the seeds it was shrunk on when it records them (meta shrink_seeds, as ppp shrink writes them), else `runs`
/// seeds derived from `seed` as ppp simulate derives them.
/// @throws IoError, ParseError naming the file (and "meta shrink_seeds" for a malformed seed list);
/// InvalidArgument naming "runs" out of range.
std::vector<CorpusCase> readCorpusCases(const std::string& corpus, std::uint64_t seed, int runs);

/// How one PPP of a corpus went: each failed run's seed and diagnosis.
struct CaseVerdict {
  int runs = 0;                           ///< Runs played.
  std::vector<std::uint64_t> failed;      ///< The seeds of the failed runs, in play order.
  std::vector<std::string> diagnoses;     ///< The diagnosis of each failed run (a diagnosis:: kind).
  double seconds = 0;                     ///< Wall time of its runs.
  bool passed() const { return failed.empty(); }
};

/// What the check node does (launch/check.launch): `ppp check` of one agent of an experiment config through the
/// simulator's evaluation service. Its `~` parameters; `ppp launch-file --check` takes the same as flags.
struct CheckTask {
  std::string config;      ///< The experiment YAML: its agents and episode rules (required).
  std::string corpus;      ///< The corpus directory or PPP file (required).
  std::string agent;       ///< The config's agent checked (required; planners included).
  std::uint64_t seed = 1;  ///< What a PPP without recorded seeds has its seeds derived from.
  int runs = kDefaultCheckRuns;  ///< How many runs such a PPP gets.
  std::string junit;       ///< Where the JUnit XML goes, its directory made if need be ("": nowhere).
  /// @throws InvalidArgument naming the option.
  void validate() const;
};

/// A check: one agent on every PPP of a corpus.
struct CheckJob {
  CheckTask task;          ///< What is checked (its config: where the agent and the rules came from, if anywhere).
  EpisodeOptions episode;  ///< The episodes' rules (for the robot's body, whether a PPP can be played at all).
  RunsPlayer play;         ///< Plays the agent on a PPP once per seed.
  /// The command that plays run `seed` of `c` again, for a failure's message.
  std::function<std::string(const CorpusCase& c, std::uint64_t seed)> replay;
};

/// Runs `job`: checks everything it can before playing (every PPP readable and playable for the robot, the JUnit
/// file writable), plays the agent on every PPP on its seeds, says on `out` how each went, and writes the JUnit XML
/// once all are played. Returns 0 when every PPP passes, 1 when any fails, 130 when `stop` said stop (nothing
/// written). @throws IoError, ParseError, InvalidArgument for bad input (nothing played, nothing written).
int runCheck(const CheckJob& job, const StopCheck& stop, std::ostream& out);

/// The JUnit XML of a check of `agent` on the corpus `suite`: one test case per PPP (its name, its file), a failure
/// naming the failed runs' diagnoses and seeds, with the command that replays each.
std::string checkJunitXml(const std::string& suite, const std::string& agent, const std::vector<CorpusCase>& cases,
                          const std::vector<CaseVerdict>& verdicts,
                          const std::function<std::string(const CorpusCase&, std::uint64_t)>& replay);

/// The launch of the check node that plays `agent` of the experiment config `config` on `corpus` (a PPP file or
/// directory) through ROS: "roslaunch launch/check.launch corpus:=... agent:=... config:=...".
std::string checkLaunchCommand(const std::string& corpus, const std::string& agent, const std::string& config);

/// One declaration per CheckTask option.
const std::vector<OptionSpec<CheckTask>>& checkTaskSpecs();

}  // namespace simulator
}  // namespace ppp
