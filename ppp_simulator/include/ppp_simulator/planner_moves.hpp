#pragma once

#include <string>
#include <vector>

#include "ppp_agents/episode_result.hpp"
#include "ppp_core/stop.hpp"

namespace ppp {
namespace simulator {

/// The file beside results.csv that keeps the actions of every planner agent's run, appended to as the runs
/// finish: a planner's run cannot be replayed (the planner is another process), so the report shows it from
/// these. Lines `set,problem,agent,run,moves`, moves one digit per action (its number in ppp/action.hpp:
/// 0 stay, 1 north, 2 east, 3 south, 4 west, 5 to 8 the diagonals).
constexpr const char* kPlannerMovesFile = "planner_moves.csv";

/// planner_moves.csv's header line, without its line break.
const std::string& plannerMovesHeader();

/// The line of `row`'s actions, with its line break.
std::string plannerMovesLine(const agents::EpisodeResult& row);

/// Gives each row of `rows` the actions that the planner moves file at `path` holds for its run: the last line of
/// that run, and only when it has as many actions as the row has steps (a line of a run played again is
/// otherwise stale). No file: the rows are unchanged. A half-written last line is left out.
/// @throws IoError, ParseError naming the file, line and field; Interrupted when `stop` says stop.
void attachPlannerMoves(const std::string& path, std::vector<agents::EpisodeResult>* rows, const StopCheck& stop = {});

/// Rewrites the planner moves file at `path` atomically with the actions of the rows that carry any, in the rows'
/// order (a finished experiment's: results.csv's canonical order), one line per run.
/// @throws IoError naming the file; Interrupted when `stop` says stop (the file is then as before).
void writePlannerMoves(const std::string& path, const std::vector<agents::EpisodeResult>& rows,
                       const StopCheck& stop = {});

}  // namespace simulator
}  // namespace ppp
