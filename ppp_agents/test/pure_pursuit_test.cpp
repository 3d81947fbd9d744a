// Pure pursuit along any-angle paths (as sampling planners give them): long segments at any angle are followed to
// the path's end, for both kinematics, staying on the path (checked against the polyline, computed apart).

#include "ppp_agents/continuous/pure_pursuit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ppp_core/motion_options.hpp"

namespace ppp {
namespace agents {
namespace {

/// The distance from (x, y) to the polyline `path`.
double distanceToPath(const std::vector<MapPoint>& path, double x, double y) {
  double best = std::hypot(path[0].x - x, path[0].y - y);
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double dx = path[i + 1].x - path[i].x, dy = path[i + 1].y - path[i].y;
    const double t = std::clamp(((x - path[i].x) * dx + (y - path[i].y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    best = std::min(best, std::hypot(path[i].x + t * dx - x, path[i].y + t * dy - y));
  }
  return best;
}

TEST(PurePursuitTest, FollowsLongSegmentsAtAnyAngleToTheEnd) {
  // A path as OMPL's simplifier leaves it: six metres down at a slant, then three shallower turns.
  const std::vector<MapPoint> path = {{0.5, 11.5}, {1.259736, 10.871630}, {2.105708, 4.991421},
                                      {3.493297, 2.138275}, {7.052380, 1.160425}, {11.5, 0.5}};
  double length = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) length += std::hypot(path[i + 1].x - path[i].x, path[i + 1].y - path[i].y);
  for (const char* kinematics : {kKinematicsDiffDrive, kKinematicsHolonomic}) {
    MotionOptions options;
    options.kinematics = kinematics;
    const KinematicLimits limits = KinematicLimits::of(options);
    PurePursuit follower;
    follower.follow(path, 1.0, limits, options.control_period);
    Pose2D pose{0.5, 11.5, 0};
    BodyVelocity velocity;
    double farthest = 0;
    // Top speed all the way takes length / speed; turning on the spot and braking at five turns, at most twice that
    // and 20 s more.
    const int periods = static_cast<int>(std::ceil((2 * length / limits.max_linear_speed + 20) / options.control_period));
    int period = 0;
    for (; period < periods && std::hypot(pose.x - 11.5, pose.y - 0.5) > 1e-3; ++period) {
      velocity = limitVelocity(follower.command(pose, velocity), velocity, limits, options.control_period);
      pose = integrate(pose, velocity, options.control_period);
      farthest = std::max(farthest, distanceToPath(path, pose.x, pose.y));
    }
    EXPECT_LT(period, periods) << kinematics << ": ended at (" << pose.x << ", " << pose.y << ")";
    EXPECT_LT(farthest, 0.02) << kinematics;
  }
}

}  // namespace
}  // namespace agents
}  // namespace ppp
