#pragma once

#include <cstdint>
#include <vector>

#include "ppp_core/grid.hpp"
#include "ppp_core/kinematics.hpp"
#include "ppp_core/laser.hpp"
#include "ppp_core/motion_options.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/square_world.hpp"

namespace ppp {

// The continuous motion model (docs/reference/continuous-motion.md): how the robot moves when `motion` is
// continuous. The grid model's counterpart is Episode (episode.hpp).

/// How one continuous run went.
struct ContinuousOutcome {
  bool passed = false;      ///< The robot's centre came within the goal tolerance of the goal cell's centre.
  int steps = 0;            ///< Control periods played.
  double seconds = 0;       ///< Simulated time.
  double distance = 0;      ///< Metres the robot's centre travelled.
  const char* reason = "";  ///< reason::kGoalReached, kBudgetExhausted, kCollision or kInvalidCommand (or another
                            ///< failure's).
  /// The robot's cell after each control period, start first (steps + 1 cells): what diagnoses read.
  std::vector<Cell> cells;
  /// The robot's pose after each control period, start first (only when asked for).
  std::vector<Pose2D> poses;
};

/// The disc's configuration space on `world`'s grid: a cell is free when a disc of `radius` metres centred on
/// the cell's centre touches no obstacle square and not the border.
Grid continuousConfigurationSpace(const SquareWorld& world, double radius);

/// Control periods in a run whose shortest route in the disc's configuration space takes `optimal_moves` moves:
/// ceil(time_factor x optimal_moves x resolution / max_linear_speed / control_period).
long continuousStepBudget(const MotionOptions& options, int optimal_moves);

/// One run in continuous motion, a control period at a time: the robot (a disc) starts at the start cell's
/// centre heading east (+x) at rest; each period it holds the velocity its command gives after the limits
/// (limitVelocity) and moves along the exact arc (integrate); the run ends when its centre is within the goal
/// tolerance of the goal cell's centre (pass), when the disc touches an obstacle square or the border
/// (collision, at the first instant of contact), when its budget of control periods is spent, or, with a
/// progress_timeout, when its centre has stayed within progress_radius of one point for that long (no_progress).
class ContinuousEpisode {
 public:
  /// A run of `problem` (decoded as `grid`) by a disc of `radius_cells` cells under
  /// `options` for at most `step_budget` control periods; the laser noise draws from `run_seed`.
  /// @throws InvalidArgument naming robot_radius when the disc cannot stand at the start.
  ContinuousEpisode(const Problem& problem, const Grid& grid, const MotionOptions& options, double radius_cells,
                    long step_budget, std::uint64_t run_seed, bool record_poses = false);
  /// True once the run ended.
  bool done() const { return done_; }
  /// The robot's pose (exact odometry).
  const Pose2D& pose() const { return pose_; }
  /// The robot's velocity, in its own frame, during the last period.
  const BodyVelocity& velocity() const { return velocity_; }
  /// Simulated seconds since the start.
  double time() const { return outcome_.seconds; }
  /// The laser's beams.
  const LaserBeams& beams() const { return beams_; }
  /// The world the robot moves in.
  const SquareWorld& world() const { return world_; }
  /// The limits of the robot.
  const KinematicLimits& limits() const { return limits_; }
  /// The goal cell's centre in the map frame.
  MapPoint goal() const { return goal_; }
  /// The robot's radius in metres.
  double radius() const { return radius_; }
  /// The laser scan at the robot's pose, into `ranges`.
  void scan(std::vector<float>* ranges);
  /// Plays one control period under `command`; a command with a number that is not finite ends the run as
  /// reason::kInvalidCommand.
  void apply(const BodyVelocity& command);
  /// Ends the run as failed for `reason`.
  void fail(const char* reason);
  /// The outcome so far (final once done()).
  const ContinuousOutcome& outcome() const { return outcome_; }

 private:
  /// Moves the robot for one period at `velocity`, stopping at the first contact; true when it touched.
  bool move(const BodyVelocity& velocity);
  void end(const char* reason, bool passed);

  SquareWorld world_;
  KinematicLimits limits_;
  LaserBeams beams_;
  double period_;
  double radius_;
  double goal_tolerance_;
  long step_budget_;
  long patience_steps_;      ///< Control periods without progress that end the run (0: never).
  double progress_radius_;   ///< Metres the robot's centre must move from the anchor to make progress.
  MapPoint anchor_;          ///< Where the robot was when it last made progress ...
  long anchor_step_ = 0;     ///< ... and after how many periods.
  MapPoint goal_;
  Rng noise_;
  Pose2D pose_;
  BodyVelocity velocity_;
  bool record_poses_;
  bool done_ = false;
  ContinuousOutcome outcome_;
};

}  // namespace ppp
