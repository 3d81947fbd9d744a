// How the bridge turns its planner's answer, a velocity command or a path, into the robot's move.
#include "planner_bridge.hpp"
#include "planner_bridge_messages.hpp"
#include "ppp_core/episode_reason.hpp"

namespace ppp {
namespace agents {

PlannerBridge::StepOutcome PlannerBridge::takeCommand(const geometry_msgs::TwistStamped& command) {
  VelocityCommand velocity;
  const std::string frame_problem = commandOf(command, parameters_.base_frame, parameters_.map_frame, &velocity);
  if (!frame_problem.empty()) return fail(reason::kInvalidCommand, frame_problem);
  const CommandedMove move = episode_.command(velocity);
  if (!move.problem.empty()) return fail(reason::kInvalidCommand, move.problem);
  following_ = {MapPoint{velocity.linear_x, velocity.linear_y}};
  return StepOutcome{static_cast<std::uint8_t>(move.action), nullptr};
}

PlannerBridge::StepOutcome PlannerBridge::followPath(const nav_msgs::Path& path) {
  const Request& r = request_;
  std::vector<MapPoint> points;
  const std::string frame_problem = pathPoints(path, parameters_.map_frame, &points);
  if (!frame_problem.empty()) return fail(reason::kInvalidPath, frame_problem);
  // The plan kept (the poses of the path being followed, sent again): the robot goes on from where it is along
  // it, rather than from the first place the path passes its cell (a path may pass a cell twice).
  if (!points.empty() && samePoints(points, following_)) {
    if (const std::optional<Action> along = episode_.next(r.robot)) {
      return StepOutcome{static_cast<std::uint8_t>(*along), nullptr};
    }
  }
  const Answer answer = episode_.answer(points, r.robot);
  if (answer.verdict == AnswerVerdict::NoPath) {
    StepOutcome failed = fail(reason::kNoPath, answer.detail);
    failed.diagnosis = episode_.noPathKind(r.robot, parameters_.robot_radius);
    return failed;
  }
  if (answer.verdict == AnswerVerdict::InvalidPath) return fail(reason::kInvalidPath, answer.detail);
  following_ = points;
  return StepOutcome{static_cast<std::uint8_t>(answer.action), nullptr};
}

bool PlannerBridge::answers(const nav_msgs::Path& path, Cell robot) const {
  std::vector<MapPoint> points;
  // A path in a wrong frame is an answer, and a wrong one: judged by the caller.
  return !pathPoints(path, parameters_.map_frame, &points).empty() || episode_.fits(points, robot);
}

}  // namespace agents
}  // namespace ppp
