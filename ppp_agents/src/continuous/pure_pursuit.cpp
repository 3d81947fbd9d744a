#include "ppp_agents/continuous/pure_pursuit.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ppp {
namespace agents {

namespace {

/// The fraction in [0, 1] of segment a-b nearest to p, and the distance to it.
std::pair<double, double> nearestOnSegment(const MapPoint& a, const MapPoint& b, double px, double py) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double squared = dx * dx + dy * dy;
  const double t = squared > 0 ? std::clamp(((px - a.x) * dx + (py - a.y) * dy) / squared, 0.0, 1.0) : 0.0;
  return {t, std::hypot(a.x + t * dx - px, a.y + t * dy - py)};
}

/// The fastest speed from which braking at `acceleration` a step each `period` (acceleration x period less each
/// period) stops within `distance`, and reaches it in no less than one period: v^2 / 2a + v T / 2 <= d, v <= d / T.
double brakingSpeed(double acceleration, double period, double distance) {
  const double brake = acceleration * period / 2;
  return std::min(std::sqrt(brake * brake + 2 * acceleration * distance) - brake, distance / period);
}

}  // namespace

void PurePursuit::follow(std::vector<MapPoint> path, double resolution, const KinematicLimits& limits,
                         double control_period) {
  path_ = std::move(path);
  remaining_.assign(path_.size(), 0);
  for (std::size_t i = path_.size(); i-- > 1;) {
    remaining_[i - 1] = remaining_[i] + std::hypot(path_[i].x - path_[i - 1].x, path_[i].y - path_[i - 1].y);
  }
  turns_.assign(path_.size(), false);
  for (std::size_t i = 1; i + 1 < path_.size(); ++i) {
    const double cross = (path_[i].x - path_[i - 1].x) * (path_[i + 1].y - path_[i].y) -
                         (path_[i].y - path_[i - 1].y) * (path_[i + 1].x - path_[i].x);
    turns_[i] = std::fabs(cross) > 1e-12;
  }
  resolution_ = resolution;
  control_period_ = control_period;
  segment_ = 0;
  passed_ = 0;
  left_ = remaining_.empty() ? 0 : remaining_[0];
  look_ahead_ = std::max(kLookAheadCells * resolution, 2 * limits.max_linear_speed * control_period);
  limits_ = limits;
}

MapPoint PurePursuit::pointAhead(std::size_t segment, double along, double distance) const {
  std::size_t i = segment;
  double t = along;
  while (i + 1 < path_.size()) {
    const double length = remaining_[i] - remaining_[i + 1];
    const double left = (1 - t) * length;
    if (distance <= left && length > 0) {
      const double s = t + distance / length;
      return MapPoint{path_[i].x + s * (path_[i + 1].x - path_[i].x), path_[i].y + s * (path_[i + 1].y - path_[i].y)};
    }
    distance -= left;
    ++i;
    t = 0;
  }
  return path_.back();
}

BodyVelocity PurePursuit::command(const Pose2D& pose, const BodyVelocity& velocity) {
  if (path_.empty()) return BodyVelocity{};
  // The nearest point moves forward only: over the segment it is on and the next ones starting within twice the
  // look-ahead of it.
  double along = 0, best = 1e300;
  std::size_t best_segment = segment_;
  for (std::size_t i = segment_; i + 1 < path_.size() && (i == segment_ || left_ - remaining_[i] <= 2 * look_ahead_);
       ++i) {
    const auto [t, distance] = nearestOnSegment(path_[i], path_[i + 1], pose.x, pose.y);
    if (distance < best - 1e-12) {
      best = distance;
      best_segment = i;
      along = t;
    }
  }
  segment_ = best_segment;
  const double here = segment_ + 1 < path_.size()
                          ? remaining_[segment_] - along * (remaining_[segment_] - remaining_[segment_ + 1])
                          : 0;  // path length left from the robot's nearest point
  left_ = here;
  // The next turn not yet reached at rest, else the end. A turn reached at rest stays passed: steering off it
  // (the next segment at any angle) moves the robot a little off the path, which must not bring it back.
  const bool moving = std::hypot(velocity.forward, velocity.left) > 0;
  std::size_t stop = path_.size() - 1;
  for (std::size_t i = std::max(segment_, passed_) + 1; i + 1 < path_.size(); ++i) {
    if (!turns_[i]) continue;
    if (here - remaining_[i] > kTurnReachedCells * resolution_ || moving) {
      stop = i;
      break;
    }
    passed_ = i;
  }
  const double to_stop = here - remaining_[stop];
  const MapPoint target = pointAhead(segment_, along, std::min(look_ahead_, std::max(to_stop, 0.0)));
  double to_end = std::hypot(path_[stop].x - pose.x, path_[stop].y - pose.y);
  to_end = std::max(to_end, to_stop);
  const double speed = std::min(limits_.max_linear_speed,
                                brakingSpeed(limits_.max_linear_acceleration, control_period_, to_end));
  const double dx = target.x - pose.x, dy = target.y - pose.y;
  const double distance = std::hypot(dx, dy);
  if (distance < 1e-12) return BodyVelocity{};
  // The target in the robot's frame.
  const double ahead = std::cos(pose.theta) * dx + std::sin(pose.theta) * dy;
  const double beside = -std::sin(pose.theta) * dx + std::cos(pose.theta) * dy;
  if (limits_.holonomic) {
    const double scale = speed / distance;
    return BodyVelocity{ahead * scale, beside * scale, 0};
  }
  const double alpha = std::atan2(beside, ahead);
  if (std::fabs(alpha) > kTurnAlignedRadians) {
    const double rate = std::min(limits_.max_angular_speed,
                                 brakingSpeed(limits_.max_angular_acceleration, control_period_, std::fabs(alpha)));
    return BodyVelocity{0, 0, std::copysign(rate, alpha)};
  }
  const double curvature = 2 * std::sin(alpha) / distance;
  double forward = speed;
  if (std::fabs(curvature) > 0) forward = std::min(forward, limits_.max_angular_speed / std::fabs(curvature));
  return BodyVelocity{forward, 0, curvature * forward};
}

}  // namespace agents
}  // namespace ppp
