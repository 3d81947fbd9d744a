#pragma once

#include "ppp_core/motion_options.hpp"

namespace ppp {

/// A robot's pose in the map frame: metres, and its heading in radians counter-clockwise from +x (east).
struct Pose2D {
  double x = 0;      ///< Metres right of the map's origin.
  double y = 0;      ///< Metres above the map's origin.
  double theta = 0;  ///< Heading, radians in (-pi, pi].
};

/// A velocity in the robot's own frame (geometry_msgs/Twist's linear x, linear y and angular z).
struct BodyVelocity {
  double forward = 0;  ///< linear.x: metres per second along the heading.
  double left = 0;     ///< linear.y: metres per second to the left of the heading (holonomic robots only).
  double turn = 0;     ///< angular.z: radians per second, counter-clockwise.
};

/// The robot's limits, from MotionOptions.
struct KinematicLimits {
  bool holonomic = false;             ///< May drive sideways (linear.y).
  double max_linear_speed = 0.5;      ///< Metres per second, the norm of (forward, left).
  double max_angular_speed = 1.5;     ///< Radians per second.
  double max_linear_acceleration = 1.0;   ///< Metres per second squared, the norm of the change of (forward, left).
  double max_angular_acceleration = 3.0;  ///< Radians per second squared.
  /// The limits `options` give.
  static KinematicLimits of(const MotionOptions& options);
};

/// The velocity a base controller holds for one period of `period` seconds when commanded `command` while moving
/// at `current`: a diff-drive robot's sideways speed is dropped; the linear speed is scaled down to the top speed
/// (its direction kept) and the turning rate clamped to its top; then the change from `current` is cut to what
/// the accelerations allow in one period (the linear change scaled along its direction). The result is reached at
/// the period's start (a step change) and held.
BodyVelocity limitVelocity(const BodyVelocity& command, const BodyVelocity& current, const KinematicLimits& limits,
                           double period);

/// The pose after moving at the constant body velocity `velocity` for `seconds` from `pose`, in closed form: a
/// straight line when not turning, else an exact arc (the body velocity turns with the robot).
Pose2D integrate(const Pose2D& pose, const BodyVelocity& velocity, double seconds);

/// `angle` wrapped into (-pi, pi].
double wrapAngle(double angle);

}  // namespace ppp
