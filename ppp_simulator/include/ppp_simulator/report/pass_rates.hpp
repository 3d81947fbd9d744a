#pragma once

#include <array>
#include <string>
#include <vector>

#include "ppp_agents/episode_result.hpp"
#include "ppp_core/diagnosis.hpp"

namespace ppp {
namespace simulator {

/// Runs per diagnosis kind (diagnosis::kKinds order), and of the loops those proven endless.
struct DiagnosisCounts {
  std::array<int, diagnosis::kKindCount> kinds{};  ///< Runs per kind.
  int endless = 0;                                 ///< Loops with an endless_step.
  int collisions = 0;                              ///< Of the `reported`, runs that ended in a collision.
  /// Counts `result`'s diagnosis.
  void add(const agents::EpisodeResult& result);
  /// Adds `other`'s counts.
  void add(const DiagnosisCounts& other);
  /// Runs of `kind` (a diagnosis:: constant).
  int of(const char* kind) const { return kinds[static_cast<std::size_t>(diagnosis::kindIndex(kind))]; }
};

/// One agent's runs on one PPP: how many, how many passed, how long they took.
struct ProblemPassRate {
  std::string set;        ///< PPP set name.
  std::string problem;    ///< PPP id within the set.
  std::string agent;      ///< Agent configuration name.
  int runs = 0;           ///< Episodes run.
  int passes = 0;         ///< Episodes that reached the goal.
  int soft_failures = 0;  ///< Of them, soft failures (longer than the soft failure ratio allows).
  DiagnosisCounts diagnoses;  ///< The runs' diagnoses.
  double mean_steps = 0;  ///< Mean actions per episode, over all runs (failed runs count their full budget).

  /// Fraction of runs that passed, in [0, 1]; 0 when there are no runs.
  double rate() const;
};

/// One agent on one PPP set: the dissertation's measure is `mean_rate`, the mean of the per-PPP rates.
struct SetPassRate {
  std::string set;       ///< PPP set name.
  std::string agent;     ///< Agent configuration name.
  int problems = 0;      ///< PPPs of the set this agent ran on.
  int runs = 0;          ///< Episodes over all those PPPs.
  int passes = 0;        ///< Episodes that passed.
  int soft_failures = 0; ///< Of them, soft failures.
  DiagnosisCounts diagnoses;  ///< The runs' diagnoses.
  double mean_rate = 0;  ///< Mean over the set's PPPs of their pass rates, in [0, 1] (not passes / runs).
};

/// Pass rates of every agent on every PPP and every set of an experiment.
struct PassRateTable {
  std::vector<std::string> sets;              ///< Set names, in report order.
  std::vector<std::string> agents;            ///< Agent names, in report order.
  std::vector<ProblemPassRate> per_problem;   ///< By set order, then PPP id (natural order), then agent order.
  std::vector<SetPassRate> per_set;           ///< By set order, then agent order; pairs without results omitted.

  /// The set-level rate of `agent` on `set`, or nullptr when that agent has no results on that set.
  const SetPassRate* find(const std::string& set, const std::string& agent) const;
  /// The per-PPP pass rates of `agent` on `set`, in per_problem order; empty when there are none.
  std::vector<double> problemRates(const std::string& set, const std::string& agent) const;
};

/// Consecutive results of one (set, PPP, agent): how many ran and passed, their steps, the first failing run.
struct ResultGroup {
  const agents::EpisodeResult* row = nullptr;         ///< The group's first result (its set, problem and agent).
  std::size_t index = 0;                      ///< Its position in the results.
  int runs = 0;                               ///< Results in the group.
  int passes = 0;                             ///< Of them, passed.
  int soft_failures = 0;                      ///< Of the passed, soft failures.
  DiagnosisCounts diagnoses;                  ///< Their diagnoses.
  double steps = 0;                           ///< Their steps, summed.
  const agents::EpisodeResult* first_fail = nullptr;  ///< The failed result with the lowest run number, or nullptr.
};

/// Groups consecutive results with the same set, problem and agent in one pass (results in canonical order give
/// one group per key; results of one key apart from each other give several groups).
std::vector<ResultGroup> groupResults(const std::vector<agents::EpisodeResult>& results);

/// Orders PPP ids naturally: runs of digits compare as numbers ("p2" < "p10"), the rest byte by byte.
bool naturalLess(const std::string& a, const std::string& b);

/// Aggregates episode results into per-PPP and per-set pass rates. `set_order` and `agent_order` give the
/// report order and must name every set and agent that occurs in `results`, each once.
/// @throws InvalidArgument naming "set_order" or "agent_order" for an empty or duplicate name, and
/// "results" for a result whose set or agent is not in the orders or whose problem id is empty.
PassRateTable computePassRates(const std::vector<agents::EpisodeResult>& results, const std::vector<std::string>& set_order,
                               const std::vector<std::string>& agent_order);

/// computePassRates() of the results `groups` were made from.
PassRateTable computeGroupedPassRates(const std::vector<ResultGroup>& groups, const std::vector<std::string>& set_order,
                               const std::vector<std::string>& agent_order);

/// The summary CSV header: level,set,problem,agent,problems,runs,passes,pass_rate,soft_failures, then the runs
/// of each diagnosis kind (stuck,loop,confined,wandering,detour,missed_route,no_route,reported) and endless_loops.
const std::vector<std::string>& summaryCsvHeader();

/// Writes the summary CSV atomically: one `problem` row per (set, PPP, agent) with problems = 1 and its pass
/// rate, then one `set` row per (set, agent) with an empty problem and the set's mean_rate; rates in [0, 1].
/// @throws IoError naming `path` when it cannot be written.
void writeSummaryCsv(const std::string& path, const PassRateTable& table);

}  // namespace simulator
}  // namespace ppp
