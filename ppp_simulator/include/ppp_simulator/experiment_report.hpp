#pragma once

#include <string>
#include <vector>

#include "ppp_agents/episode_result.hpp"
#include "ppp_simulator/experiment_config.hpp"
#include "ppp_simulator/experiment_runner.hpp"
#include "ppp_simulator/report/pass_rates.hpp"
#include "ppp_simulator/report/report.hpp"

namespace ppp {
namespace simulator {

/// Largest map side whose failing runs the report animates (at most the experiment's animation_frames frames, 3
/// pixels per cell or more); larger maps get the still picture only, which keeps the report's time bounded.
constexpr int kReportAnimationMaxSide = 100;

/// The hardest PPPs of an experiment (lowest mean pass rate over every agent but the astar control), each with
/// the first failing run of the agent it hurts most (largest drop below that agent's mean pass rate over all
/// PPPs), replayed to recover its path and animated (maps up to kReportAnimationMaxSide); `groups` are the
/// experiment's results grouped (groupResults()). @throws Interrupted when `stop`, asked before each failure
/// and each frame, says stop.
std::vector<FailureExample> hardestFailures(const ExperimentConfig& config, const std::vector<agents::PreparedSet>& sets,
                                            const std::vector<ResultGroup>& groups, int count,
                                            const StopCheck& stop = {});

/// Per agent (but the astar control and the random baseline), the first failing run on its worst PPP (lowest pass
/// rate over every set; the first of equals), replayed for its path and animated as above (a planner's from the
/// actions its row carries, planner_moves.csv, or in continuous motion from its commands, played again by
/// `planner_rows`; left out when it has none, it plays differently, or the map is too large to animate);
/// agents that never fail are left out. With the config's shrink_worst, each run's PPP is shrunk for its seed
/// (FailureExample::shrunk): a built-in agent's in process, a planner's when `planner_rows` can play it; one agent
/// per thread (the config's threads), the result in agent order whatever the threads.
/// @throws Interrupted as hardestFailures().
std::vector<FailureExample> worstFailures(const ExperimentConfig& config, const std::vector<agents::PreparedSet>& sets,
                                          const std::vector<ResultGroup>& groups, const StopCheck& stop = {},
                                          const PlannerRows& planner_rows = {});

/// Per agent shown in the report (as worstFailures()) that has a failed or soft-failed run in `rows`, its runs
/// grouped by failure signature (FailureGrouping): the kShownFailureKinds most common, each with the smallest PPP
/// it happened on (fewest obstacle cells), that run's diagnosis and seed, and the agent's replay flags (none for a
/// planner). The PPPs are the sets' own: the report writes them, so a set published by a generator node elsewhere
/// serves as well as one in the output directory.
std::vector<AgentFailureKinds> failureKinds(const ExperimentConfig& config, const std::vector<agents::PreparedSet>& sets,
                                            const std::vector<agents::EpisodeResult>& rows);

/// Per agent (as worstFailures()), its longest passed run on the PPP of `detours` (detourStats() of the results)
/// where its passed runs were longest against the optimum, replayed and animated; agents with no passed run are
/// left out; a planner's run in continuous motion is played again by `planner_rows` to be drawn, and left out
/// without it. @throws Interrupted as hardestFailures().
std::vector<FailureExample> longestDetours(const ExperimentConfig& config, const std::vector<agents::PreparedSet>& sets,
                                           const std::vector<DetourStats>& detours, const StopCheck& stop = {},
                                           const PlannerRows& planner_rows = {});

/// Writes summary.csv and report.{md,html} (with plots and pictures) of a finished experiment into `dir`;
/// `stop` is asked between the pieces (the pass rates, the failures replayed, each picture and file);
/// `planner_rows` plays planners for the shrunk worst PPPs (worstFailures()).
/// @throws IoError, Interrupted (every file written by then is whole: a rerun writes them all again).
void writeExperimentReport(const std::string& dir, const ExperimentConfig& config, const std::string& config_text,
                           const std::vector<agents::PreparedSet>& sets, const std::vector<agents::EpisodeResult>& rows,
                           const StopCheck& stop = {}, const PlannerRows& planner_rows = {});

}  // namespace simulator
}  // namespace ppp
