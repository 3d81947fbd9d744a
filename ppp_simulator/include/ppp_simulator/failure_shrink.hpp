#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_agents/episode_result.hpp"
#include "ppp_core/diagnosis.hpp"
#include "ppp_core/episode_options.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/shrink.hpp"
#include "ppp_core/stop.hpp"

namespace ppp {
namespace simulator {

/// How the runs of one agent with given seeds went on one PPP, as results.csv would record them.
struct RunsOutcome {
  bool valid = true;  ///< The PPP is one the robot can solve (agents::prepareSet accepts it); nothing ran if not.
  int runs = 0;       ///< Runs played.
  int failed = 0;     ///< Of them, failed or soft-failed (diagnosed).
  std::array<int, diagnosis::kKindCount> kinds{};  ///< Failed and soft-failed runs per diagnosis kind.
  int endless = 0;    ///< Of the loops, those proven endless (a lockstep planner's; never a built-in agent's).
  std::map<std::string, int> signatures;  ///< Failed and soft-failed runs per failure signature.
};

/// What the runs `rows` (one agent's on one PPP, as results.csv has them) came to.
RunsOutcome outcomeOfRows(const std::vector<agents::EpisodeResult>& rows);

/// Run seeds as a shrunk PPP's meta shrink_seeds lists them: "11,42".
std::string seedList(const std::vector<std::uint64_t>& seeds);

/// Whether the robot can solve `problem` under `episode` (its goal reachable, for its body): a shrink's candidates
/// must be.
bool solvableForRobot(const Problem& problem, const EpisodeOptions& episode);

/// Plays the built-in agent `agent` on `problem` once per seed of `seeds` (results.csv's run seeds) under
/// `episode`, each run diagnosed as in an experiment.
RunsOutcome playRuns(const Problem& problem, const agents::AgentConfig& agent, const EpisodeOptions& episode,
                     const std::vector<std::uint64_t>& seeds);

/// Plays the agent a shrink judges on a PPP once per seed: playRuns() in process for a built-in agent; through the
/// simulator's evaluation service for any agent of an experiment, planners included.
using RunsPlayer = std::function<RunsOutcome(const Problem& problem, const std::vector<std::uint64_t>& seeds)>;

/// Plays an agent on a solvable PPP once per seed and gives the rows, as results.csv has them (a planner's with its
/// actions): the simulator node's planner lanes, for the report's shrunk planner failures.
using RowsPlayer =
    std::function<std::vector<agents::EpisodeResult>(const Problem& problem, const std::vector<std::uint64_t>& seeds)>;

/// A RunsPlayer on `rows`: outcomeOfRows() of its rows, a PPP the robot cannot solve under `episode` judged invalid
/// without playing it.
RunsPlayer playerOfRows(RowsPlayer rows, const EpisodeOptions& episode);

/// The failure a shrink keeps: at least `failures` of the judged runs fail, with diagnosis `kind` unless it is
/// empty, as loops proven endless when `endless`.
struct FailureToKeep {
  std::string kind;      ///< A diagnosis:: kind, or "" for any failure.
  int failures = 0;      ///< Runs that must fail (so).
  bool endless = false;  ///< Only with kind loop: those runs' loops must be proven endless.
  /// The failure in words: "loop", "endless loop", "any failure".
  std::string text() const;
};

/// What `outcome` shows: with `any_kind`, its failures of any kind; otherwise the most common diagnosis among its
/// failed runs (a tie goes to the kind first in diagnosis::kKinds) and how many runs it had, as endless loops when
/// every loop among them was proven endless.
FailureToKeep failureShown(const RunsOutcome& outcome, bool any_kind);

/// How a shrink judges its candidates: one agent's runs with given seeds.
struct FailureJudging {
  agents::AgentConfig agent;         ///< The agent (a built-in one unless `play` is given).
  EpisodeOptions episode;            ///< The episode's rules.
  RunsPlayer play;                   ///< How its runs are played; empty: playRuns() in process.
  std::vector<std::uint64_t> seeds;  ///< The run seeds (results.csv's seed column).
  bool any_kind = false;             ///< Keep any failure, not only the original's most common diagnosis.
  /// Keep candidates on which at least this share of the runs fail so, in (0, 1]; 0: the original's share.
  double min_rate = 0;
  /// @throws InvalidArgument naming "seeds" (none) or "min_rate".
  void validate() const;
  /// `play`, or playRuns() in process when it is empty.
  RunsPlayer player() const;
};

/// The first of `judging`'s seeds on which its agent fails `problem` (played one at a time), or the first seed
/// when it fails on none.
std::uint64_t firstFailingSeed(const Problem& problem, const FailureJudging& judging);

/// Whether `outcome` is a valid PPP's and still shows `keep`.
bool stillShows(const RunsOutcome& outcome, const FailureToKeep& keep);

/// A shrunk failure and what it took.
struct ShrunkFailure {
  Problem problem;         ///< The 1-minimal PPP, its metadata saying where it came from (shrunk_from, ...).
  FailureToKeep kept;      ///< The failure kept.
  RunsOutcome before;      ///< The original's runs.
  RunsOutcome after;       ///< The shrunk PPP's runs.
  int evaluations = 0;     ///< Candidates judged.
  int descriptors_before = 0;  ///< Descriptors of the original.
  int descriptors_after = 0;   ///< And of the result.
  int cells_before = 0;        ///< Obstacle cells of the original's grid.
  int cells_after = 0;         ///< And of the result's.
};

/// Shrinks `problem` (named `source` in the result's metadata) for `judging`'s agent and runs, keeping
/// failureShown() of the original's runs, at least `min_rate` of them when given (shrinkProblem() over `units`).
/// The result's metadata drops the original's measures (character.*), gives it the failure fitness (fitness
/// failure, fitness_value the share of the judged runs failing so) and adds shrunk_from,
/// shrink_agent, shrink_seeds, shrink_kind, shrink_failed ("3 of 3"), shrink_endless (true, for endless loops
/// kept), descriptors_before/after,
/// obstacle_cells_before/after and shrink_evaluations.
/// @throws InvalidArgument naming "problem" when the original does not fail so (nothing to shrink) or is not
/// solvable for the robot, as FailureJudging::validate(); Interrupted when `stop` says stop.
ShrunkFailure shrinkFailure(const Problem& problem, const std::string& source, const FailureJudging& judging,
                            ShrinkUnits units, const StopCheck& stop = {});

}  // namespace simulator
}  // namespace ppp
