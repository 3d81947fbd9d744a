#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ppp_core/action.hpp"
#include "ppp_agents/agent.hpp"
#include "ppp_agents/agent_memory.hpp"
#include "ppp_agents/path_follower.hpp"
#include "ppp_agents/planner_bridge_options.hpp"
#include "ppp_agents/velocity_command.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/map_frame.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {
namespace agents {

/// How a planner's answer to a plan request ended the wait.
enum class AnswerVerdict {
  Move,         ///< A usable path: the robot takes its first move.
  NoPath,       ///< The planner found no path (an empty answer).
  InvalidPath,  ///< The path is unusable (off the map, not through the robot, through a known wall, not to the goal).
};

/// The result of judging an answer.
struct Answer {
  AnswerVerdict verdict = AnswerVerdict::Move;  ///< What the answer amounts to.
  Action action = Action::Stay;                  ///< The move, for AnswerVerdict::Move.
  std::string detail;                            ///< What is wrong, otherwise.
};

/// One episode of a planner agent as planner_bridge_node plays it, without ROS: what the robot knows (its
/// memory with the agent's memory handicap, or the true map), the planner's path it follows, and the verdicts
/// on the planner's paths (docs/reference/planner-interface.md).
class PlannerEpisode {
 public:
  /// Starts an episode on a width x height map; `prior` is the true map for agents given it, else null.
  void start(const EpisodeInfo& info, const Grid* prior, int memory_window, double resolution);
  /// Takes the step's scan into the memory (a robot given the true map has nothing to learn); true when what the
  /// robot knows changed.
  bool observe(const Scan& scan);
  /// The move along the current path when a lockstep bridge with `options` needs no plan request at the step last
  /// observed (docs/reference/planner-interface.md, "plan_requests"): the robot moved since the step before, its path gives
  /// it a move and, unless the rule is on_blocked, that scan changed nothing the robot knows. Nothing otherwise.
  std::optional<Action> moveWithoutRequest(const BridgeOptions& options);
  /// A path the planner published unasked: followed from now on when usable, ignored otherwise.
  void offer(const std::vector<MapPoint>& points, Cell robot);
  /// The move along the current path, or nothing when the planner must be asked for a path.
  std::optional<Action> next(Cell robot);
  /// True when `points` answer a request made with the robot at `robot`: a usable path, or an empty one (the
  /// planner's "no path"). Anything else may be a late answer to an earlier request.
  bool fits(const std::vector<MapPoint>& points, Cell robot) const;
  /// Judges the planner's answer to a request; a usable path is followed from now on.
  Answer answer(const std::vector<MapPoint>& points, Cell robot);
  /// The move a local planner's velocity command gives the robot (commandedMove, with the episode's connectivity
  /// and resolution).
  CommandedMove command(const VelocityCommand& command) const {
    return commandedMove(command, connectivity_, frame_.resolution);
  }
  /// A digest of the episode's whole decision state (the robot's cell and the one before, whether the last scan
  /// changed what it knows, what it knows, the path it follows and its place on it) and `following`, the
  /// planner's last answer (its path's waypoints, or its velocity command as one point (linear x, linear y)): equal digests at two steps mean the bridge, and a planner that is
  /// a function of its input (pose, map, goal), will act the same from both.
  std::uint64_t stateDigest(const std::vector<MapPoint>& following) const;
  /// For a planner that answered "no path" with the robot at `robot`: diagnosis::kMissedRoute when the map it
  /// was given had a route to the goal for a robot of `robot_radius` cells through cells not known to be
  /// obstacles, else diagnosis::kNoRoute.
  const char* noPathKind(Cell robot, double robot_radius) const;
  /// What the robot knows: kScanFree / kScanObstacle / kScanUnknown per cell.
  const KnownMap& known() const { return known_; }
  /// The map's frame (size and resolution).
  const MapFrame& frame() const { return frame_; }
  /// The goal cell.
  Cell goal() const { return goal_; }

 private:
  MapFrame frame_;
  Cell goal_;
  Connectivity connectivity_ = Connectivity::Four;
  bool has_prior_ = false;
  Cell position_{-1, -1};  // the robot's cell at the step last observed
  Cell previous_{-1, -1};  // and at the step before (none at an episode's first step)
  bool changed_ = false;   // whether the last observed scan changed what the robot knows
  AgentMemory memory_;
  KnownMap known_;
  PathFollower follower_;
};

}  // namespace agents
}  // namespace ppp
