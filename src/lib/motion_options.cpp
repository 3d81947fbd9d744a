#include "ppp_core/motion_options.hpp"

#include "ppp_core/option_yaml.hpp"

namespace ppp {

void MotionOptions::validate() const { checkOptionRanges(motionOptionSpecs(), *this); }

const std::vector<OptionSpec<MotionOptions>>& motionOptionSpecs() {
  using M = MotionOptions;
  constexpr double kPositive = 1e-9;  // the least value of an option that must be positive
  static const std::vector<OptionSpec<M>> specs = {
      declareOption("motion", "how the robot moves", +[](M& m) -> std::string& { return m.motion; })
          .withChoices("motion",
                       {{kMotionGrid, "one cell per action, no heading or velocity (the default)"},
                        {kMotionContinuous,
                         "a velocity held each control period, a heading and a 2D laser, among square cells"}}),
      declareOption("kinematics", "continuous motion: how the robot may move",
                    +[](M& m) -> std::string& { return m.kinematics; })
          .withChoices("kinematics", {{kKinematicsDiffDrive, "along its heading, turning on the spot or in arcs"},
                                      {kKinematicsHolonomic, "in any direction, turning or not"}}),
      declareOption("resolution", "continuous motion: metres per PPP cell",
                    +[](M& m) -> double& { return m.resolution; }, Bounds{kPositive, kMaxMotionMagnitude}),
      declareOption("control_period", "continuous motion: seconds each velocity command is held",
                    +[](M& m) -> double& { return m.control_period; }, Bounds{kPositive, 60}),
      declareOption("max_linear_speed", "continuous motion: top speed in metres per second",
                    +[](M& m) -> double& { return m.max_linear_speed; }, Bounds{kPositive, kMaxMotionMagnitude}),
      declareOption("max_angular_speed", "continuous motion: top turning rate in radians per second",
                    +[](M& m) -> double& { return m.max_angular_speed; }, Bounds{kPositive, kMaxMotionMagnitude}),
      declareOption("max_linear_acceleration", "continuous motion: metres per second squared",
                    +[](M& m) -> double& { return m.max_linear_acceleration; },
                    Bounds{kPositive, kMaxMotionMagnitude}),
      declareOption("max_angular_acceleration", "continuous motion: radians per second squared",
                    +[](M& m) -> double& { return m.max_angular_acceleration; },
                    Bounds{kPositive, kMaxMotionMagnitude}),
      declareOption("laser_beams", "continuous motion: beams per laser scan, evenly over its field of view",
                    +[](M& m) -> int& { return m.laser_beams; }, Bounds{1, kMaxLaserBeams}),
      declareOption("laser_field_of_view", "continuous motion: the laser's field of view in degrees, centred ahead",
                    +[](M& m) -> double& { return m.laser_field_of_view; }, Bounds{kPositive, 360}),
      declareOption("laser_range", "continuous motion: the laser's range in metres (farther: no return, +inf)",
                    +[](M& m) -> double& { return m.laser_range; }, Bounds{kPositive, kMaxMotionMagnitude}),
      declareOption("laser_noise",
                    "continuous motion: standard deviation in metres of the Gaussian noise on each range (from the "
                    "run's seed)",
                    +[](M& m) -> double& { return m.laser_noise; }, Bounds{0, kMaxMotionMagnitude}),
      declareOption("goal_tolerance",
                    "continuous motion: the goal is reached when the robot's centre is this near the goal cell's "
                    "centre, in cells",
                    +[](M& m) -> double& { return m.goal_tolerance; }, Bounds{kPositive, 0.5}),
      declareOption("time_factor",
                    "continuous motion: a run's budget of simulated time is this factor x the time its shortest "
                    "route takes at top speed",
                    +[](M& m) -> double& { return m.time_factor; }, Bounds{1, 1000}),
      declareOption("progress_timeout",
                    "continuous motion: a run whose robot stays within progress_radius of one point for this many "
                    "seconds of simulated time ends as no_progress (a patience timer); 0: never",
                    +[](M& m) -> double& { return m.progress_timeout; }, Bounds{0, kMaxMotionMagnitude}),
      declareOption("progress_radius", "continuous motion: cells the robot's centre must move to make progress",
                    +[](M& m) -> double& { return m.progress_radius; }, Bounds{kPositive, 1000}),
  };
  return specs;
}

}  // namespace ppp
