#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "ppp_core/option_spec.hpp"
#include "ppp_core/stop.hpp"
#include "ppp_simulator/experiment_config.hpp"
#include "ppp_simulator/failure_shrink.hpp"

namespace ppp {
namespace simulator {

/// Most runs a shrink judges per PPP.
constexpr int kMaxJudgedRuns = 100000;

/// One shrink, as `ppp shrink` runs it in process and the shrink node through ROS: what is shrunk, where it
/// goes and how candidates are judged.
struct ShrinkJob {
  std::string input;   ///< A .ppp, map_server .yaml or MovingAI .map file, or a set directory.
  std::string output;  ///< The shrunk .ppp file, or a new directory for a set ("": none, with `corpus`).
  /// A corpus directory each shrunk PPP is added to (Corpus: once per obstacle shape), after the output is
  /// written; "": none.
  std::string corpus;
  /// The agent, its episode rules, how its runs are played and on which seeds (replaced per PPP by `results`').
  FailureJudging judging;
  /// An experiment's results.csv: judge each PPP on the seeds of the agent's failed runs there (its set is the
  /// PPP's directory name); "" for judging.seeds.
  std::string results;
  int results_runs = 3;  ///< At most this many of each PPP's failed runs in `results`.
  std::string units;     ///< "descriptors", "cells", or "" (descriptors for .ppp files, cells for imported maps).
  /// The command that plays the shrunk PPP in `file` again on run `seed`, for a set's list of distinct traps
  /// (empty: none said).
  std::function<std::string(const std::string& file, std::uint64_t seed)> replay;
  /// @throws InvalidArgument naming "by" (units), "input" (missing), "output" (neither it nor a corpus given; a set's
  /// output directory exists and is not empty), as FailureJudging::validate().
  void validate() const;
};

/// Runs `job`: shrinks the input (each PPP of a set the agent fails), writes the result only once every PPP is
/// done, and says what each shrink kept on `out` ("9 -> 1 descriptors, 87 -> 1 obstacle cells, still loop in 3 of
/// 3 runs"), for a set then its shrunk PPPs grouped by trap (distinctFailureLine(), with `replay`'s command on the
/// written file: the corpus's when there is one); why nothing was written goes to `err`. Returns the exit status: 0 when written, 1 when the agent
/// fails nothing (nothing written), 130 when `stop` said stop (nothing written).
/// @throws InvalidArgument naming the option ("results": no failed run of the PPP there) or the input's
/// "problem", IoError, ParseError.
int runShrinkJob(const ShrinkJob& job, const StopCheck& stop, std::ostream& out, std::ostream& err);

/// The run seeds `ppp shrink --runs N --seed S` judges: N seeds derived from S as `ppp simulate` derives them.
/// @throws InvalidArgument naming "runs" unless N is in [1, kMaxJudgedRuns].
std::vector<std::uint64_t> derivedRunSeeds(std::uint64_t seed, int runs);

/// What the shrink node does (launch/shrink.launch): the shrink of one agent of an experiment config through
/// the simulator's evaluation service. Its `~` parameters; `ppp launch-file --shrink` takes the same as flags.
struct ShrinkTask {
  std::string config;       ///< The experiment YAML: its agents and episode rules (required).
  std::string input;        ///< The PPP file or set directory to shrink (required).
  std::string output;       ///< The shrunk .ppp file, or a new directory for a set (required unless `corpus`).
  std::string corpus;       ///< A corpus directory each shrunk PPP is added to, once per obstacle shape.
  std::string agent;        ///< The config's agent whose failure is shrunk (required; planners included).
  std::uint64_t seed = 1;   ///< The failing run's seed, or with `runs` the seed theirs derive from.
  int runs = 0;             ///< Judge this many runs seeded from `seed` (0: `seed` alone; with `results`: 3).
  std::string results;      ///< An experiment's results.csv: judge each PPP on the agent's failed runs' seeds.
  double min_rate = 0;      ///< Keep candidates failing at least this share of the runs (0: the original's).
  bool any_kind = false;    ///< Keep any failure, not only the original's most common diagnosis.
  std::string by;           ///< descriptors, cells, or "" (by the file's kind).
  /// @throws InvalidArgument naming the option.
  void validate() const;
};

/// One declaration per ShrinkTask option.
const std::vector<OptionSpec<ShrinkTask>>& shrinkTaskSpecs();

/// The job `task` describes for `agent` of its config under `episode`, its runs played by `play`.
/// @throws InvalidArgument as ShrinkJob::validate().
ShrinkJob shrinkJobOf(const ShrinkTask& task, const agents::AgentConfig& agent, const EpisodeOptions& episode,
                      RunsPlayer play);

}  // namespace simulator
}  // namespace ppp
