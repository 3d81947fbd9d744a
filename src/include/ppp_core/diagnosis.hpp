#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "ppp_core/grid.hpp"

namespace ppp {

/// What kind of failure a run was: results.csv's `diagnosis` (docs/reference/diagnoses.md). A closed set.
namespace diagnosis {
// The budget ran out (reason budget_exhausted or action_limit); judged over the run's final window
// (finalWindow()).
constexpr const char* kStuck = "stuck";          ///< The robot's cell did not change over the final window.
constexpr const char* kLoop = "loop";            ///< Its cells repeat with a period p >= 2 to the end.
constexpr const char* kConfined = "confined";    ///< Not periodic, but it reached no cell it had not stood on before.
constexpr const char* kWandering = "wandering";  ///< It still reached cells it had never stood on.
/// A passed run longer than the soft failure ratio x the optimal length.
constexpr const char* kDetour = "detour";
/// no_path, while the map the planner was given had a route for the robot's body through cells not known to be
/// obstacles: the planner missed it.
constexpr const char* kMissedRoute = "missed_route";
/// no_path, and the planner's map had no such route: what the robot knew was wrong (sensor noise, forgetting).
constexpr const char* kNoRoute = "no_route";
/// Any other ending the agent or the planner caused (invalid_path, collision, planner_timeout, ...): the reason
/// column says it all.
constexpr const char* kReported = "reported";
/// Every kind, in the order of summary.csv's and the report's columns.
constexpr const char* kKinds[] = {kStuck, kLoop, kConfined, kWandering, kDetour, kMissedRoute, kNoRoute, kReported};
/// The number of kinds.
constexpr int kKindCount = static_cast<int>(sizeof kKinds / sizeof kKinds[0]);
/// The kind constant equal to `text`, or nullptr.
const char* kindNamed(std::string_view text);
/// The position of `text` in kKinds, or -1.
int kindIndex(std::string_view text);
}  // namespace diagnosis

/// A run's diagnosis. Steps count actions: step t is the robot's cell after t actions (step 0 is the start).
struct Diagnosis {
  const char* kind = "";  ///< A diagnosis:: constant, or "" for a clean pass.
  /// loop: the first step of the periodic tail; stuck: the step since which the cell did not change; confined:
  /// the step since which every cell was one stood on before; wandering: the last step that reached a new cell.
  /// -1 for the other kinds.
  int step = -1;
  int period = 0;  ///< loop: actions per cycle; 0 otherwise.
  /// loop of an agent that reports its whole decision state (a lockstep planner bridge): the first step t of the
  /// tail whose state recurred at t + period, so that an agent which is a function of its input repeats the
  /// cycle forever; -1 when not proven.
  int endless_step = -1;
};

/// The actions of a run of `steps` actions over which stuck, loop and confined are judged: the last quarter
/// (rounded up), at least min(steps, 4).
int finalWindow(int steps);

/// The diagnosis of a run whose budget ran out. `cells[t]` is the robot's cell after t actions (cells.size() =
/// actions + 1). `states`, when not empty, holds per action t (0-based, one per action) a digest of the agent's
/// whole decision state as it chose that action (0: none given); it can prove a loop endless.
Diagnosis diagnoseTrajectory(const std::vector<Cell>& cells, const std::vector<std::uint64_t>& states = {});

/// The diagnosis of a continuous run whose budget ran out (docs/reference/continuous-motion.md). `cells[t]` is the
/// robot's cell after t control periods. stuck, confined and wandering are judged as diagnoseTrajectory() judges
/// them, over the final window of control periods; a loop on the cells the robot entered (each cell once per
/// entry, however long it stayed): the smallest period p >= 2 of that sequence over a tail that covers the final
/// window and two whole cycles. `step` is then the control period at which the tail begins, and `period` counts
/// the cells entered per cycle. A loop is never proven endless here.
Diagnosis diagnoseContinuousTrajectory(const std::vector<Cell>& cells);

/// diagnoseRun() of a continuous run: diagnoseContinuousTrajectory() for a budget ending.
Diagnosis diagnoseContinuousRun(bool passed, bool soft_failure, const std::string& reason,
                                const std::vector<Cell>& cells);

/// The diagnosis of any run: "" for a pass that is not a soft failure, detour for a soft one, the trajectory's
/// for a budget ending (reason budget_exhausted or action_limit), `reported_kind` when the agent gave one for
/// its own ending (missed_route or no_route), else reported.
Diagnosis diagnoseRun(bool passed, bool soft_failure, const std::string& reason, const std::vector<Cell>& cells,
                      const std::vector<std::uint64_t>& states = {}, const char* reported_kind = nullptr);

/// The distinct cells of a loop's cycle in `cells` (a run diagnosed `d`), in the order first met; empty for
/// anything but a loop or when `cells` is shorter than the cycle.
std::vector<Cell> cycleCells(const Diagnosis& d, const std::vector<Cell>& cells);

/// `d` in words, for the report and `ppp replay`, e.g. "loop: from step 56 the robot repeats a cycle of 2 actions
/// over 2 cells to the end (endless: ...)". `reason` is the run's reason; `cycle_cells` the number of distinct
/// cells of a loop's cycle (0: not known).
std::string describeDiagnosis(const Diagnosis& d, const std::string& reason, int cycle_cells = 0);

}  // namespace ppp
