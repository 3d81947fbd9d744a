#pragma once

#include <string>

namespace ppp {

/// Why an episode ended: results.csv's `reason`, ppp_msgs/EpisodeResults and ppp_msgs/EpisodeFailure.
namespace reason {
constexpr const char* kGoalReached = "goal_reached";          ///< Pass: the agent stands on the goal.
constexpr const char* kBudgetExhausted = "budget_exhausted";  ///< Fail: the move budget is spent.
/// Fail: the action limit of an episode whose stays or bumps are free (BudgetRule::actionLimit()) is reached.
constexpr const char* kActionLimit = "action_limit";
constexpr const char* kTimeout = "timeout";                   ///< Fail (ROS): the agent did not answer in time.
constexpr const char* kAgentLost = "agent_lost";              ///< Fail (ROS): the agent process went away.
constexpr const char* kInvalidAction = "invalid_action";      ///< Fail (ROS): the agent sent something unusable.
constexpr const char* kNoPath = "no_path";                    ///< Fail (planner): it published an empty path.
constexpr const char* kInvalidPath = "invalid_path";          ///< Fail (planner): its path was unusable.
/// Fail (local planner): its velocity command was unusable (not a number, or an absurd speed).
constexpr const char* kInvalidCommand = "invalid_command";
constexpr const char* kPlannerTimeout = "planner_timeout";    ///< Fail (planner): no path in time.
constexpr const char* kPlannerLost = "planner_lost";          ///< Fail (planner): its process went away.
/// Fail (local planner): it gave up on its goal (an actionlib_msgs/GoalStatus ABORTED instead of a command).
constexpr const char* kPlannerAborted = "planner_aborted";
constexpr const char* kCollision = "collision";  ///< Fail (planner, robot with a body): it drove into an obstacle.
/// Fail (continuous motion with a progress_timeout): the robot stayed near one point for that long.
constexpr const char* kNoProgress = "no_progress";
/// The reason constant equal to `text` among those an agent may report itself (the planner ones), or
/// nullptr.
const char* agentReportedReason(const std::string& text);
/// The reason constant equal to `text` among all of them, or nullptr.
const char* reasonNamed(const std::string& text);
}  // namespace reason

}  // namespace ppp
