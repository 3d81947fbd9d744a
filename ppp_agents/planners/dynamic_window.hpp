#pragma once

#include <functional>
#include <vector>

#include "ppp_core/kinematics.hpp"
#include "ppp_core/map_frame.hpp"

namespace ppp {
namespace planners {

/// How the dynamic window weighs and rolls out its candidates (the DWA node's `~` parameters).
struct DynamicWindowOptions {
  double sim_time = 1.5;        ///< Seconds each candidate velocity is rolled out for.
  int linear_samples = 4;       ///< Forward speeds sampled (holonomic: rings of velocities).
  int angular_samples = 15;     ///< Turning rates sampled (holonomic: directions per ring).
  double goal_bias = 1.0;       ///< Weight of the rollout's end's distance to the goal, per metre.
  double clearance_bias = 0.5;  ///< Weight of coming nearer than `clearance_scale` to an obstacle.
  double clearance_scale = 0.5; ///< Metres of clearance beyond which an obstacle costs nothing.
  bool grid_moves = false;      ///< The grid model: the candidates are standing and top speed along each of the
                                ///< map's four axes, the moves the grid takes (it rounds any other direction).
  double safety_margin = 0.05;  ///< Metres a rollout must keep between the disc and every obstacle point: the
                                ///< scan samples a wall at points a beam's gap apart, and a disc (or a point) can
                                ///< pass between two of them only through the wall.
};

/// A dynamic-window local planner (Fox, Burgard and Thrun, 1997) as ROS's dwa_local_planner works: each control
/// period it samples the velocities the robot can reach within one period (its accelerations) and its limits,
/// rolls each out at constant velocity for `sim_time` seconds (exact arcs), drops those whose rollout comes
/// within the robot's radius plus `safety_margin` of an obstacle point, and takes the cheapest of the rest:
///   goal_bias x (the rollout's end's distance to the goal: a costmap's wavefront, or the straight line)
///   + clearance_bias x max(0, 1 - clearance / clearance_scale)      (clearance: nearest approach minus radius)
/// ties going to the first sampled (diff drive: the slowest speed, then the most clockwise turn).
/// When no candidate is admissible, none has a known route to the goal, or the best is standing still, a
/// diff-drive robot turns in place (move_base's rotate recovery) towards the way down the route: the lowest goal
/// distance among points half a metre around it. A holonomic one stands.
class DynamicWindow {
 public:
  /// `limits`: the robot's (infinite accelerations: every velocity within the limits is reachable, as on the
  /// grid); `period`: seconds a command is held; `radius`: the robot's disc in metres.
  /// @throws InvalidArgument naming the option when a limit, the period, the radius or an option is out of range.
  DynamicWindow(const KinematicLimits& limits, double period, double radius, const DynamicWindowOptions& options);

  /// Metres to the goal from a point in the robot's frame (+infinity: no known route).
  using GoalDistance = std::function<double(MapPoint)>;

  /// The velocity for a robot moving at `current` (its own frame) among `obstacles` (points in its frame,
  /// metres), bound for `goal` (in its frame), the rollouts' ends scored by `goal_distance` (empty: the straight
  /// line to `goal`).
  BodyVelocity choose(const std::vector<MapPoint>& obstacles, MapPoint goal, const BodyVelocity& current,
                      const GoalDistance& goal_distance = {}) const;

 private:
  /// The velocities sampled in the window around `current`.
  std::vector<BodyVelocity> candidates(const BodyVelocity& current) const;
  /// The rollout's cost, or a negative number when it comes within the radius of an obstacle.
  double cost(const BodyVelocity& velocity, const std::vector<MapPoint>& obstacles,
              const GoalDistance& goal_distance) const;

  KinematicLimits limits_;
  double period_;
  double radius_;
  DynamicWindowOptions options_;
};

}  // namespace planners
}  // namespace ppp
