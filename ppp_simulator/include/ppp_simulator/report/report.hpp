#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ppp_core/diagnosis.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/kinematics.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/stop.hpp"
#include "ppp_simulator/report/detours.hpp"
#include "ppp_simulator/report/distinct_failures.hpp"
#include "ppp_simulator/report/motion_models.hpp"
#include "ppp_simulator/report/pass_rates.hpp"
#include "ppp_simulator/report/reference.hpp"

namespace ppp {
namespace simulator {

/// A run in continuous motion, drawn as the robot's trajectory rather than by its cells.
struct DrivenRun {
  std::vector<ppp::Pose2D> poses;  ///< The robot's pose after each control period, start first.
  double resolution = 1;           ///< Metres per cell.
  double radius = 0;               ///< The robot's radius, metres.
  double distance = 0;             ///< Metres its centre travelled.
};

/// A pictured run's PPP shrunk to the smallest on which the run still fails the same way (ppp shrink).
struct ShrunkExample {
  ppp::Problem ppp;              ///< The 1-minimal PPP; its metadata says where it came from.
  std::vector<ppp::Cell> path;   ///< The run's cells on it, from the start.
  std::optional<DrivenRun> driven;  ///< In continuous motion: the run's trajectory, its picture.
  std::vector<ppp::Cell> cycle;  ///< A loop's cycle cells, pink on its picture; else empty.
  std::string summary;           ///< "1 of 10 descriptors, 1 of 54 obstacle cells, still loop in 1 of 1 runs".
  std::string animation_gif;     ///< The run on it frame by frame; empty when the map is too large to animate.
};

/// A failed run on one of the hardest PPPs (the runner chooses them), with what a test engineer needs to
/// see the failure and replay it.
struct FailureExample {
  std::string set;              ///< PPP set name.
  std::string problem;          ///< PPP id within the set.
  std::string agent;            ///< Agent configuration name.
  int run = 0;                  ///< Run number, 0-based.
  std::uint64_t seed = 0;       ///< Seed of that run.
  ppp::Problem ppp;             ///< The PPP itself.
  std::vector<ppp::Cell> path;  ///< Cells the agent stood on, in order, from the start (may be empty).
  std::optional<DrivenRun> driven;  ///< In continuous motion: the run's trajectory, its picture (path: its cells).
  std::string reason;           ///< Why the episode ended (a reason:: constant).
  ppp::Diagnosis diagnosis;     ///< The run's diagnosis (results.csv's).
  std::vector<ppp::Cell> cycle; ///< A loop's cycle cells (cycleCells()), marked on the picture; else empty.
  std::string replay_flags;     ///< `ppp replay` flags recreating the agent configuration (e.g. "--agent explorer
                                ///< --memory 5x5"); empty means "--agent <agent>".
  std::string animation_gif;    ///< The run frame by frame (animateEpisode's GIF bytes); empty when there is none.
  bool recorded = false;        ///< A planner's run, drawn from its moves in planner_moves.csv or, in continuous
                                ///< motion, from the commands it sent (`ppp replay` cannot play a planner).
  std::optional<ShrunkExample> shrunk;  ///< Its PPP shrunk, when the report shows it.
};

/// One way an agent failed: its failed runs of one failure signature, with the smallest PPP they happened on and
/// what plays its run there again (the report writes the PPP under ppps/failures/).
struct FailureKind {
  DistinctFailure failure;  ///< The signature, its runs and PPPs, and the smallest PPP's obstacle cells.
  std::string diagnosis;    ///< The diagnosis of its run on the smallest PPP (a diagnosis:: kind).
  std::string set;          ///< The smallest PPP's set.
  std::string problem;      ///< And its id there.
  ppp::Problem ppp;         ///< The PPP.
  std::uint64_t seed = 0;   ///< The seed of the run on it.
  /// `ppp replay` flags recreating the agent ("--agent explorer --memory 5"); empty for a planner, whose run is
  /// played again by its shrink through ROS on the seed.
  std::string replay_flags;
};

/// An agent's failures by signature ("Faults found", "Distinct failures").
struct AgentFailureKinds {
  std::string agent;               ///< The agent.
  int kinds = 0;                   ///< Its different signatures.
  int runs = 0;                    ///< Its failed and soft-failed runs.
  std::vector<FailureKind> shown;  ///< The most common kinds, most common first (at most kShownFailureKinds).
};

/// The most kinds of failure the report lists per agent.
constexpr int kShownFailureKinds = 8;

/// What the report says about a set besides its pass rates.
struct SetInfo {
  std::string name;         ///< Set name, as in the pass-rate table.
  double diversity = 0;     ///< Its diversity figure (generator::setDiversity).
  std::string archive_svg;  ///< Its MAP-Elites archive heat map (SVG), empty when it was not hunted with one.
};

/// PPPs an agent fails: its pass rate on them is below this.
constexpr double kFailedBelow = 0.5;

/// Everything the report shows.
struct ReportInput {
  std::string title;        ///< Report heading.
  std::string config_text;  ///< The experiment YAML, shown verbatim.
  std::string control;      ///< Name of the control agent (it knows the map), explained in the guide; may be empty.
  PassRateTable rates;      ///< Pass rates of every agent on every PPP and set.
  std::vector<std::pair<std::string, std::string>> comparisons;  ///< Set pairs to compare, usually the first two.
  std::vector<FailureExample> failures;                          ///< Hardest PPPs with a failing path each.
  std::vector<FailureExample> worst;  ///< Per agent, a failing run on its worst PPP ("Faults found").
  std::vector<AgentFailureKinds> failure_kinds;  ///< Per agent that fails, its failures by signature ("Faults found").
  std::vector<DetourStats> detours;   ///< Path / optimal of passed runs per set and agent ("Detours").
  std::vector<FailureExample> detour_examples;  ///< Per agent, its longest run on its worst-detour PPP.
  std::vector<SetInfo> sets;          ///< Diversity and archive of each set (may be empty).
  std::vector<ReferenceComparison> references;  ///< Published rates beside the measured ones ("Reference").
  std::vector<MotionPair> motion_pairs;         ///< Agents played in both motion models ("Both motion models").
};

/// Writes the experiment report into `dir` (created if missing), replacing files of the same names (the
/// "Faults found" section counts, per agent and set, the PPPs passed in under kFailedBelow of the runs, and
/// shows `worst` and the sets' archives):
/// `report.md` (Markdown, referring to the files below by relative path), `report.html` (self-contained: the
/// same content with inline SVG charts and base64 PNG pictures, nothing fetched), `plots/pass_rate_by_agent.svg`,
/// `plots/pass_rate_by_ppp_<set>.svg` per set (a heat map), `plots/path_ratio.svg` (the detours' box plot,
/// when there are any), and per failure and detour example (hardest and worst) `pictures/<set>_<problem>_<agent>.png`
/// (the PPP with the agent's path), beside it `.gif` (the run animated, when the example has one; inline in the
/// HTML too) and `ppps/<set>_<problem>.ppp` (the PPP, for `ppp replay`). Names are
/// reduced to letters, digits, '.', '-' and '_' in file names. Every file is written atomically.
/// Everything is checked and rendered before the first file is written.
/// @throws InvalidArgument naming "comparisons" for a pair naming a set the table does not have, and
/// "failures" (with the example's index and the renderer's message) for an invalid PPP or a path cell off
/// its grid; IoError naming the file or directory that cannot be written; Interrupted when `stop`, asked
/// before each picture and each file, says stop (the files written by then are whole).
void writeReport(const std::string& dir, const ReportInput& input, const StopCheck& stop = {});

}  // namespace simulator
}  // namespace ppp
