#include "dynamic_window.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "ppp_core/error.hpp"

namespace ppp {
namespace planners {
namespace {

/// Longest step between two checked poses of a rollout, in metres (dwa_local_planner's sim_granularity).
constexpr double kGranularity = 0.05;
/// The recovery looks for the way down the route at this many points this far around the robot (metres).
constexpr int kRecoveryDirections = 16;
constexpr double kRecoveryReach = 0.5;
/// A velocity whose components add up to less than this (m/s and rad/s) stands still.
constexpr double kStill = 1e-9;

/// `count` values evenly from `low` to `high` (`low` alone when there is one or the range is empty).
std::vector<double> evenly(double low, double high, int count) {
  if (count <= 1 || !(high > low)) return {low};
  std::vector<double> values;
  for (int k = 0; k < count; ++k) values.push_back(low + (high - low) * k / (count - 1));
  return values;
}

void requirePositive(double value, const char* name) {
  if (!(value > 0) || !std::isfinite(value)) {
    throw InvalidArgument(name, "expected a positive finite number, got " + std::to_string(value));
  }
}

}  // namespace

DynamicWindow::DynamicWindow(const KinematicLimits& limits, double period, double radius,
                             const DynamicWindowOptions& options)
    : limits_(limits), period_(period), radius_(radius), options_(options) {
  // Named as the node's parameters and the motion options name them.
  requirePositive(limits.max_linear_speed, "max_linear_speed");
  requirePositive(limits.max_angular_speed, "max_angular_speed");
  if (!(limits.max_linear_acceleration > 0)) {
    throw InvalidArgument("max_linear_acceleration", "expected a positive number");
  }
  if (!(limits.max_angular_acceleration > 0)) {
    throw InvalidArgument("max_angular_acceleration", "expected a positive number");
  }
  requirePositive(period, "control_period");
  if (!(radius >= 0) || !std::isfinite(radius)) throw InvalidArgument("robot_radius", "expected metres >= 0");
  requirePositive(options.sim_time, "sim_time");
  if (options.linear_samples < 1 || options.linear_samples > 100) {
    throw InvalidArgument("linear_samples", "expected 1 to 100");
  }
  if (options.angular_samples < 1 || options.angular_samples > 100) {
    throw InvalidArgument("angular_samples", "expected 1 to 100");
  }
  if (!(options.goal_bias >= 0) || !(options.clearance_bias >= 0) || !std::isfinite(options.goal_bias) ||
      !std::isfinite(options.clearance_bias)) {
    throw InvalidArgument("goal_bias", "goal_bias and clearance_bias: expected finite numbers >= 0");
  }
  requirePositive(options.clearance_scale, "clearance_scale");
  if (!(options.safety_margin >= 0) || !std::isfinite(options.safety_margin)) {
    throw InvalidArgument("safety_margin", "expected metres >= 0");
  }
}

std::vector<BodyVelocity> DynamicWindow::candidates(const BodyVelocity& current) const {
  const double reach = limits_.max_linear_acceleration * period_;
  std::vector<BodyVelocity> result;
  if (options_.grid_moves) {
    const double top = limits_.max_linear_speed;
    return {{0, 0, 0}, {top, 0, 0}, {0, top, 0}, {-top, 0, 0}, {0, -top, 0}};
  }
  if (!limits_.holonomic) {
    const double turn_reach = limits_.max_angular_acceleration * period_;
    const std::vector<double> speeds = evenly(std::max(0.0, current.forward - reach),
                                              std::min(limits_.max_linear_speed, current.forward + reach),
                                              options_.linear_samples);
    const std::vector<double> turns = evenly(std::max(-limits_.max_angular_speed, current.turn - turn_reach),
                                             std::min(limits_.max_angular_speed, current.turn + turn_reach),
                                             options_.angular_samples);
    for (double speed : speeds) {
      for (double turn : turns) result.push_back({speed, 0, turn});
    }
    return result;
  }
  // Holonomic: the current velocity and rings around it out to what one period's acceleration reaches, in
  // angular_samples directions, each scaled back to the top speed.
  const double radius = std::min(reach, 2 * limits_.max_linear_speed);
  result.push_back({current.forward, current.left, 0});
  for (int ring = 1; ring <= options_.linear_samples; ++ring) {
    for (int k = 0; k < options_.angular_samples; ++k) {
      const double angle = 2 * M_PI * k / options_.angular_samples;
      const double r = radius * ring / options_.linear_samples;
      result.push_back({current.forward + r * std::cos(angle), current.left + r * std::sin(angle), 0});
    }
  }
  for (BodyVelocity& v : result) {
    const double speed = std::hypot(v.forward, v.left);
    if (speed > limits_.max_linear_speed) {
      v.forward *= limits_.max_linear_speed / speed;
      v.left *= limits_.max_linear_speed / speed;
    }
  }
  return result;
}

double DynamicWindow::cost(const BodyVelocity& velocity, const std::vector<MapPoint>& obstacles,
                           const GoalDistance& goal_distance) const {
  const double distance = std::hypot(velocity.forward, velocity.left) * options_.sim_time;
  const int steps = std::max(static_cast<int>(std::ceil(options_.sim_time / period_)),
                             static_cast<int>(std::ceil(distance / kGranularity)));
  const double keep_off = radius_ + options_.safety_margin;
  double nearest_squared = std::numeric_limits<double>::infinity();
  Pose2D end;
  for (int k = 1; k <= steps; ++k) {
    end = integrate(Pose2D{}, velocity, options_.sim_time * k / steps);
    for (const MapPoint& p : obstacles) {
      const double dx = p.x - end.x, dy = p.y - end.y;
      nearest_squared = std::min(nearest_squared, dx * dx + dy * dy);
    }
    if (nearest_squared <= keep_off * keep_off) return -1;
  }
  const double clearance = std::sqrt(nearest_squared) - radius_;
  return options_.goal_bias * goal_distance({end.x, end.y}) +
         options_.clearance_bias * std::max(0.0, 1 - clearance / options_.clearance_scale);
}

BodyVelocity DynamicWindow::choose(const std::vector<MapPoint>& obstacles, MapPoint goal, const BodyVelocity& current,
                                   const GoalDistance& goal_distance) const {
  const GoalDistance straight = [goal](MapPoint p) { return std::hypot(goal.x - p.x, goal.y - p.y); };
  const GoalDistance& distance = goal_distance ? goal_distance : straight;
  // Only obstacles a rollout can come near matter.
  const double horizon = limits_.max_linear_speed * options_.sim_time + radius_ +
                         std::max(options_.clearance_scale, options_.safety_margin);
  std::vector<MapPoint> near;
  for (const MapPoint& p : obstacles) {
    if (std::hypot(p.x, p.y) <= horizon) near.push_back(p);
  }
  BodyVelocity best;
  double best_cost = std::numeric_limits<double>::infinity();
  for (const BodyVelocity& candidate : candidates(current)) {
    const double c = cost(candidate, near, distance);
    if (c >= 0 && c < best_cost) {
      best_cost = c;
      best = candidate;
    }
  }
  const bool standing = std::abs(best.forward) + std::abs(best.left) + std::abs(best.turn) < kStill;
  if (limits_.holonomic || (std::isfinite(best_cost) && !standing)) return best;
  // Recovery: turn in place towards the way down the route (the lowest of kRecoveryDirections points around).
  double lowest = std::numeric_limits<double>::infinity(), towards = std::atan2(goal.y, goal.x);
  for (int k = 0; k < kRecoveryDirections; ++k) {
    const double angle = -M_PI + 2 * M_PI * k / kRecoveryDirections;
    const double d = distance({kRecoveryReach * std::cos(angle), kRecoveryReach * std::sin(angle)});
    if (d < lowest) {
      lowest = d;
      towards = angle;
    }
  }
  return {0, 0, (towards >= 0 ? 1.0 : -1.0) * limits_.max_angular_speed};
}

}  // namespace planners
}  // namespace ppp
