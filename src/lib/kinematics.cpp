#include "ppp_core/kinematics.hpp"

#include <algorithm>
#include <cmath>

namespace ppp {

KinematicLimits KinematicLimits::of(const MotionOptions& options) {
  KinematicLimits limits;
  limits.holonomic = options.holonomic();
  limits.max_linear_speed = options.max_linear_speed;
  limits.max_angular_speed = options.max_angular_speed;
  limits.max_linear_acceleration = options.max_linear_acceleration;
  limits.max_angular_acceleration = options.max_angular_acceleration;
  return limits;
}

BodyVelocity limitVelocity(const BodyVelocity& command, const BodyVelocity& current, const KinematicLimits& limits,
                           double period) {
  BodyVelocity wanted = command;
  if (!limits.holonomic) wanted.left = 0;
  const double speed = std::hypot(wanted.forward, wanted.left);
  if (speed > limits.max_linear_speed) {
    wanted.forward *= limits.max_linear_speed / speed;
    wanted.left *= limits.max_linear_speed / speed;
  }
  wanted.turn = std::clamp(wanted.turn, -limits.max_angular_speed, limits.max_angular_speed);
  const double change_forward = wanted.forward - current.forward, change_left = wanted.left - current.left;
  const double change = std::hypot(change_forward, change_left);
  const double most_change = limits.max_linear_acceleration * period;
  BodyVelocity held = wanted;
  if (change > most_change) {
    held.forward = current.forward + change_forward * most_change / change;
    held.left = current.left + change_left * most_change / change;
  }
  const double most_turn_change = limits.max_angular_acceleration * period;
  held.turn = current.turn + std::clamp(wanted.turn - current.turn, -most_turn_change, most_turn_change);
  return held;
}

Pose2D integrate(const Pose2D& pose, const BodyVelocity& velocity, double seconds) {
  const double turned = velocity.turn * seconds;
  // Displacement in the robot's starting frame: the integral of R(turn * s) (forward, left) over [0, seconds].
  double along, across;
  if (std::fabs(turned) < 1e-9) {
    // sin(a)/w and (1 - cos(a))/w by their series, exact to double precision for tiny angles.
    along = velocity.forward * seconds * (1 - turned * turned / 6) - velocity.left * seconds * turned / 2;
    across = velocity.left * seconds * (1 - turned * turned / 6) + velocity.forward * seconds * turned / 2;
  } else {
    const double s = std::sin(turned) / velocity.turn, c = (1 - std::cos(turned)) / velocity.turn;
    along = velocity.forward * s - velocity.left * c;
    across = velocity.forward * c + velocity.left * s;
  }
  const double cos_theta = std::cos(pose.theta), sin_theta = std::sin(pose.theta);
  return Pose2D{pose.x + cos_theta * along - sin_theta * across, pose.y + sin_theta * along + cos_theta * across,
                wrapAngle(pose.theta + turned)};
}

double wrapAngle(double angle) {
  constexpr double kPi = 3.14159265358979323846;
  double wrapped = std::remainder(angle, 2 * kPi);
  if (wrapped <= -kPi) wrapped += 2 * kPi;
  return wrapped;
}

}  // namespace ppp
