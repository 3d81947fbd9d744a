#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ppp {
namespace simulator {

/// Why an episode ended.
namespace reason {
constexpr const char* kGoalReached = "goal_reached";          ///< Pass: the agent stands on the goal.
constexpr const char* kBudgetExhausted = "budget_exhausted";  ///< Fail: the move budget is spent.
constexpr const char* kTimeout = "timeout";                   ///< Fail (ROS): the agent did not answer in time.
constexpr const char* kAgentLost = "agent_lost";              ///< Fail (ROS): the agent process went away.
constexpr const char* kInvalidAction = "invalid_action";      ///< Fail (ROS): the agent sent something unusable.
constexpr const char* kNoPath = "no_path";                    ///< Fail (planner): it published an empty path.
constexpr const char* kInvalidPath = "invalid_path";          ///< Fail (planner): its path was unusable.
constexpr const char* kPlannerTimeout = "planner_timeout";    ///< Fail (planner): no path in time.
constexpr const char* kPlannerLost = "planner_lost";          ///< Fail (planner): its process went away.
/// The reason constant equal to `text` among those an agent may report itself (the four planner ones), or
/// nullptr.
const char* agentReportedReason(const std::string& text);
}  // namespace reason

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
  int path_length = 0;      ///< Cells actually moved.
  int optimal_length = 0;   ///< Fewest moves from start to goal (the DPA's fewest advances).
  std::string reason;       ///< One of the reason:: constants.
};

/// The results.csv header: set,problem,agent,run,seed,pass,steps,bumps,path_length,optimal_length,reason.
const std::vector<std::string>& resultCsvHeader();

/// A result as CSV fields in header order (pass as 1/0).
std::vector<std::string> toCsvFields(const EpisodeResult& result);

/// Parses CSV fields in header order. @throws ParseError naming `source`, `line` and the field.
EpisodeResult fromCsvFields(const std::vector<std::string>& fields, const std::string& source, int line);

/// Splits one CSV line into fields (RFC 4180 quoting). @throws ParseError for an unterminated quote.
std::vector<std::string> splitCsvLine(const std::string& line, const std::string& source, int line_number);

}  // namespace simulator
}  // namespace ppp
