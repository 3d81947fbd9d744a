#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ppp_agents/continuous/continuous_agent.hpp"
#include "ppp_agents/continuous/laser_memory.hpp"
#include "ppp_agents/continuous/pure_pursuit.hpp"

namespace ppp {
namespace agents {

/// What a path planner's answer did: nothing wrong, or the run's failure reason (reason::kNoPath or
/// reason::kInvalidPath) and what was wrong.
struct PlanVerdict {
  const char* failure = nullptr;  ///< nullptr: the robot follows the path.
  std::string detail;
};

/// A path planner (interface path) driven in continuous motion, as the planner bridge plays it: the robot's map
/// (the true map when the planner is given it, else a LaserMemory of the run's scans), when to ask the planner
/// for a path (plan_requests), the judgement of each answer, and the pure pursuit along the path taken (the
/// follower astar drives with). The planner is asked at a run's first period, and then:
/// - every_step: every control period;
/// - on_change: when the robot's map gained a cell, when the robot stands at its path's end, or when the path
///   ahead enters a cell the map knows as an obstacle;
/// - on_blocked: only at the path's end or when the path ahead enters a known obstacle.
/// An empty path fails the run as no_path; a path with a point off the map, or none within a cell of the robot,
/// as invalid_path. A path equal to the one followed is kept where the robot is along it.
class PlanFollower {
 public:
  /// A new run, as the robot is told of it, asking as `plan_requests` (a kPlanRequests... value) says.
  void start(const ContinuousStart& start, const std::string& plan_requests);
  /// Takes one period's sensing into the robot's map. @return true when the planner is to be asked this period.
  bool observe(const ContinuousSensing& sensing);
  /// The robot's map: one value per grid cell in grid order (row 0 at the top), kScan... values.
  const std::vector<std::int8_t>& map() const { return prior_.empty() ? memory_.cells() : prior_; }
  /// Takes the planner's answer to this period's request, for the robot at `pose`.
  PlanVerdict take(const std::vector<MapPoint>& path, const Pose2D& pose);
  /// This period's velocity command: along the path taken (standing still before the first).
  BodyVelocity command(const ContinuousSensing& sensing);

 private:
  /// True when the path ahead of the robot's nearest point enters a cell the map knows as an obstacle.
  bool pathBlocked() const;
  /// True when the robot stands at the end of its path.
  bool atPathEnd(const Pose2D& pose) const;

  ContinuousStart start_;
  std::string plan_requests_;
  std::vector<std::int8_t> prior_;  // the true map, as kScan... values; empty without one
  LaserMemory memory_;
  bool asked_ = false;              // the planner has been asked in this run
  std::vector<MapPoint> path_;      // the path taken
  PurePursuit follower_;
};

}  // namespace agents
}  // namespace ppp
