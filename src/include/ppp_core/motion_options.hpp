#pragma once

#include <string>
#include <vector>

#include "ppp_core/option_spec.hpp"

namespace ppp {

// How the robot moves (docs/reference/continuous-motion.md): on the grid, one cell per action (the default and
// the dissertation's model), or continuously, with a velocity, a heading and a 2D laser, among the PPP's cells
// drawn as squares of `resolution` metres.

/// motion: one cell per action, 4- or 8-connected (the default).
constexpr const char* kMotionGrid = "grid";
/// motion: a velocity held for each control period, a heading, a 2D laser (ContinuousEpisode).
constexpr const char* kMotionContinuous = "continuous";
/// kinematics: the robot drives in any direction of its own frame (linear x and y) and turns (angular z).
constexpr const char* kKinematicsHolonomic = "holonomic";
/// kinematics: the robot drives along its heading (linear x) and turns (angular z), as a differential drive.
constexpr const char* kKinematicsDiffDrive = "diff_drive";

/// Largest number of laser beams.
constexpr int kMaxLaserBeams = 100000;
/// Largest cell side, laser range or speed limit a continuous model takes (metres, metres per second).
constexpr double kMaxMotionMagnitude = 1e6;

/// The continuous motion model's world, robot and laser (used when `motion` is continuous).
struct MotionOptions {
  std::string motion = kMotionGrid;                 ///< kMotionGrid or kMotionContinuous.
  std::string kinematics = kKinematicsDiffDrive;    ///< kKinematicsHolonomic or kKinematicsDiffDrive.
  double resolution = 1.0;         ///< Metres per PPP cell (robot_radius, in cells, scales with it).
  double control_period = 0.1;     ///< Seconds each velocity command is held.
  double max_linear_speed = 0.5;   ///< Metres per second, along any direction.
  double max_angular_speed = 1.5;  ///< Radians per second.
  double max_linear_acceleration = 1.0;   ///< Metres per second squared.
  double max_angular_acceleration = 3.0;  ///< Radians per second squared.
  int laser_beams = 360;           ///< Beams per scan, evenly over the field of view.
  double laser_field_of_view = 360;  ///< Degrees, centred on the robot's heading.
  double laser_range = 3.5;        ///< Metres: farther returns read +infinity (no return).
  double laser_noise = 0;          ///< Standard deviation of the Gaussian noise on each range, in metres.
  double goal_tolerance = 0.25;    ///< The goal is reached when the robot's centre is this near the goal cell's
                                   ///< centre, in cells.
  double time_factor = 4;          ///< A run's budget of simulated time: factor x the time the optimal route
                                   ///< takes at top speed (ContinuousEpisode).
  double progress_timeout = 0;     ///< Seconds of simulated time a run may stay within progress_radius of one
                                   ///< point before it ends as no_progress; 0: never (the default).
  double progress_radius = 0.5;    ///< Cells the robot's centre must move to make progress.
  /// True for a holonomic robot.
  bool holonomic() const { return kinematics == kKinematicsHolonomic; }
  /// @throws InvalidArgument naming the option.
  void validate() const;
};

/// One declaration per motion option (experiment YAML keys, `ppp simulate` flags).
const std::vector<OptionSpec<MotionOptions>>& motionOptionSpecs();

}  // namespace ppp
