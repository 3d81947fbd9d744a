#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "ppp_agents/protocol/batch_types.hpp"
#include "ppp_core/action.hpp"
#include "ppp_core/diagnosis.hpp"
#include "ppp_core/kinematics.hpp"

namespace ppp {
namespace agents {

/// One row of results.csv: one agent's run on one PPP.
struct EpisodeResult {
  std::string set;          ///< PPP set name.
  std::string problem;      ///< PPP id within the set.
  std::string agent;        ///< Agent configuration name.
  int run = 0;              ///< Run number, 0-based.
  std::uint64_t seed = 0;   ///< Seed of this run (agent choices and sensor noise derive from it).
  bool passed = false;      ///< Reached the goal within the budget.
  int steps = 0;            ///< Actions taken.
  int bumps = 0;            ///< Actions that hit an obstacle or the edge.
  double path_length = 0;     ///< Length moved: 1 per straight move, sqrt(2) per diagonal (connectivity 8).
  double optimal_length = 0;  ///< Optimal length from start to goal: the DPA's fewest advances, or the octile
                              ///< length under connectivity 8.
  std::string reason;       ///< One of the reason:: constants.
  bool soft_failure = false;  ///< Passed, but on a path longer than the soft failure ratio x the optimal length.
  std::string diagnosis;    ///< What kind of failure (a diagnosis:: constant), "" for a clean pass.
  int diagnosis_step = -1;  ///< Diagnosis::step (-1: none; an empty field).
  int loop_period = 0;      ///< Diagnosis::period (0: not a loop; an empty field).
  int endless_step = -1;    ///< Diagnosis::endless_step (-1: not proven endless; an empty field).
  /// How and where the run failed (failureSignature(); docs/reference/signatures.md), "" for a clean pass.
  std::string signature;
  /// Planner agents played by an AgentLane: every action of the run in order (not in results.csv; the simulator
  /// keeps them in planner_moves.csv so the report can show the run); empty otherwise.
  std::vector<Action> actions;
  /// Planner agents played by a ContinuousLane: the velocity commanded in each control period, in order (not
  /// written anywhere; what the report draws the run from); empty otherwise.
  std::vector<BodyVelocity> commands;
};

/// The results.csv header: set,problem,agent,run,seed,pass,steps,bumps,path_length,optimal_length,reason,
/// soft_failure,diagnosis,diagnosis_step,loop_period,endless_step,signature.
const std::vector<std::string>& resultCsvHeader();

/// A result as CSV fields in header order (pass and soft_failure as 1/0; a missing diagnosis step, period or
/// endless step as an empty field).
std::vector<std::string> toCsvFields(const EpisodeResult& result);

/// Sets the diagnosis fields of `result` to `d`.
void setDiagnosis(const Diagnosis& d, EpisodeResult* result);

/// The diagnosis fields of `result`.
Diagnosis diagnosisOf(const EpisodeResult& result);

/// Parses CSV fields in header order. @throws ParseError naming `source`, `line` and the field.
EpisodeResult fromCsvFields(const std::vector<std::string>& fields, const std::string& source, int line);

/// Appends `result` as one CSV line with its line break: the same text as csvLine(toCsvFields(result)) + '\n',
/// without the intermediate fields.
void appendCsvRow(const EpisodeResult& result, std::string* out);

/// Parses one CSV line (without its line break): the same result and errors as
/// fromCsvFields(splitCsvLine(line)), without copying fields that need no unquoting.
EpisodeResult parseCsvRow(std::string_view line, const std::string& source, int line_number);

/// Splits one CSV line into fields (RFC 4180 quoting). @throws ParseError for an unterminated quote.
std::vector<std::string> splitCsvLine(const std::string& line, const std::string& source, int line_number);

}  // namespace agents
}  // namespace ppp
