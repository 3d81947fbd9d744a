// The dynamic window's choices in situations whose answer follows by hand from its definition, checked against an
// independent fine rollout where the answer is a property (no collision) rather than a value.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "dynamic_window.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace planners {
namespace {

KinematicLimits diffDrive() {
  KinematicLimits limits;  // 0.5 m/s, 1.5 rad/s, 1 m/s^2, 3 rad/s^2
  limits.holonomic = false;
  return limits;
}

/// A wall across the robot's way at x = `x`, points 1 cm apart from y = -1 to 1.
std::vector<MapPoint> wallAhead(double x) {
  std::vector<MapPoint> points;
  for (int k = -100; k <= 100; ++k) points.push_back({x, k * 0.01});
  return points;
}

TEST(DynamicWindowTest, AtRestInTheOpenItAcceleratesStraightAtTheGoal) {
  // From rest one period of 1 m/s^2 reaches 0.1 m/s; going straight brings the rollout's end nearest the goal.
  const DynamicWindow window(diffDrive(), 0.1, 0.2, DynamicWindowOptions{});
  const BodyVelocity chosen = window.choose({}, {5, 0}, {});
  EXPECT_DOUBLE_EQ(chosen.forward, 0.1);
  EXPECT_DOUBLE_EQ(chosen.left, 0);
  EXPECT_NEAR(chosen.turn, 0, 1e-12);
}

TEST(DynamicWindowTest, AGoalToTheLeftTurnsItCounterClockwiseAtTheWindowsEdge) {
  // Goal at (0, 5): the arc (0.1 m/s, +0.3 rad/s) ends at about (0.145, 0.033), 4.967 m from it, nearer than the
  // straight line's (0.15, 0) at 5.002 m or standing at 5 m; +0.3 is the most one period of 3 rad/s^2 reaches.
  const DynamicWindow window(diffDrive(), 0.1, 0, DynamicWindowOptions{});
  const BodyVelocity chosen = window.choose({}, {0, 5}, {});
  EXPECT_DOUBLE_EQ(chosen.forward, 0.1);
  EXPECT_NEAR(chosen.turn, 0.3, 1e-12);
}

TEST(DynamicWindowTest, WithUnboundedAccelerationsAHolonomicRobotGoesAtTopSpeedInTheSampledDirectionNearestTheGoal) {
  // Every velocity up to 0.5 m/s is in the window; 15 directions 24 degrees apart; the goal at (3, 4) lies at
  // 53.13 degrees, nearest the second direction (48 degrees).
  KinematicLimits limits;
  limits.holonomic = true;
  limits.max_linear_acceleration = std::numeric_limits<double>::infinity();
  limits.max_angular_acceleration = std::numeric_limits<double>::infinity();
  const DynamicWindow window(limits, 0.1, 0, DynamicWindowOptions{});
  const BodyVelocity chosen = window.choose({}, {3, 4}, {});
  EXPECT_NEAR(chosen.forward, 0.5 * std::cos(2 * 2 * M_PI / 15), 1e-12);
  EXPECT_NEAR(chosen.left, 0.5 * std::sin(2 * 2 * M_PI / 15), 1e-12);
  EXPECT_EQ(chosen.turn, 0);
}

TEST(DynamicWindowTest, OnTheGridItTakesTheMoveWhoseRolloutEndsNearestTheGoal) {
  // The grid's moves at 0.5 m/s for 1.5 s end 0.75 m along an axis: for the goal at (3, 4) north ends 4.42 m
  // from it, east 4.59 m. A wall 0.6 m to the north (a disc of 0.2 m and a margin of 0.05 m cannot roll 0.75 m
  // towards it) leaves east. Boxed in on all four sides it stands.
  KinematicLimits limits;
  limits.holonomic = true;
  limits.max_linear_acceleration = std::numeric_limits<double>::infinity();
  limits.max_angular_acceleration = std::numeric_limits<double>::infinity();
  DynamicWindowOptions options;
  options.grid_moves = true;
  const DynamicWindow window(limits, 1.0, 0.2, options);
  const BodyVelocity north = window.choose({}, {3, 4}, {});
  EXPECT_EQ(north.forward, 0);
  EXPECT_EQ(north.left, 0.5);
  std::vector<MapPoint> wall;
  for (int k = -100; k <= 100; ++k) wall.push_back({k * 0.01, 0.6});
  const BodyVelocity east = window.choose(wall, {3, 4}, {});
  EXPECT_EQ(east.forward, 0.5);
  EXPECT_EQ(east.left, 0);
  std::vector<MapPoint> box;
  for (int k = -100; k <= 100; ++k) {
    box.insert(box.end(), {{k * 0.01, 0.6}, {k * 0.01, -0.6}, {0.6, k * 0.01}, {-0.6, k * 0.01}});
  }
  const BodyVelocity stand = window.choose(box, {3, 4}, {});
  EXPECT_EQ(stand.forward, 0);
  EXPECT_EQ(stand.left, 0);
}

TEST(DynamicWindowTest, ItNeverChoosesARolloutThatComesWithinTheRadiusOfAWall) {
  // A wall 0.3 m ahead, a disc of 0.2 m, the goal behind the wall; moving at 0.05 m/s. Whatever it chooses, an
  // independent rollout 1 mm apart keeps the disc off the wall for the whole 1.5 s.
  const double radius = 0.2;
  const DynamicWindow window(diffDrive(), 0.1, radius, DynamicWindowOptions{});
  const std::vector<MapPoint> wall = wallAhead(0.3);
  for (double speed : {0.0, 0.05}) {
    const BodyVelocity chosen = window.choose(wall, {5, 0.5}, {speed, 0, 0});
    const double seconds = 1.5;
    const double distance = std::hypot(chosen.forward, chosen.left) * seconds;
    const int steps = std::max(1, static_cast<int>(std::ceil(distance / 0.001)));
    for (int k = 0; k <= steps; ++k) {
      const Pose2D at = integrate(Pose2D{}, chosen, seconds * k / steps);
      for (const MapPoint& p : wall) {
        ASSERT_GE(std::hypot(p.x - at.x, p.y - at.y), radius - 1e-9)
            << "from " << speed << " m/s: (" << chosen.forward << ", " << chosen.turn << ") hits the wall at t = "
            << seconds * k / steps;
      }
    }
  }
}

TEST(DynamicWindowTest, TouchingAnObstacleADiffDriveRobotTurnsInPlaceTowardsTheGoal) {
  // Every rollout starts inside the disc's clearance: none is admissible, so it turns in place (rotate recovery)
  // at its top rate, counter-clockwise for a goal on its left, clockwise for one on its right.
  const DynamicWindow window(diffDrive(), 0.1, 0.2, DynamicWindowOptions{});
  const std::vector<MapPoint> touching = wallAhead(0.1);
  const BodyVelocity left = window.choose(touching, {0, 3}, {});
  EXPECT_EQ(left.forward, 0);
  EXPECT_EQ(left.turn, 1.5);
  EXPECT_EQ(window.choose(touching, {0, -3}, {}).turn, -1.5);
}

TEST(DynamicWindowTest, ObstaclesBeyondReachChangeNothing) {
  // Points beyond what any rollout can come near (0.75 m of travel + 0.2 m radius + 0.5 m clearance scale).
  const DynamicWindow window(diffDrive(), 0.1, 0.2, DynamicWindowOptions{});
  std::vector<MapPoint> far;
  for (int k = 0; k < 360; ++k) far.push_back({1.5 * std::cos(k * M_PI / 180), 1.5 * std::sin(k * M_PI / 180)});
  const BodyVelocity free = window.choose({}, {2, 1}, {0.2, 0, 0.1});
  const BodyVelocity ringed = window.choose(far, {2, 1}, {0.2, 0, 0.1});
  EXPECT_EQ(free.forward, ringed.forward);
  EXPECT_EQ(free.turn, ringed.turn);
}

TEST(DynamicWindowTest, BadLimitsAndOptionsAreRefusedByName) {
  const auto refused = [](const KinematicLimits& limits, double period, double radius, DynamicWindowOptions options,
                          const char* name) {
    try {
      DynamicWindow(limits, period, radius, options);
      ADD_FAILURE() << "accepted a bad " << name;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.name(), name);
    }
  };
  KinematicLimits no_speed = diffDrive();
  no_speed.max_linear_speed = 0;
  refused(no_speed, 0.1, 0, {}, "max_linear_speed");
  KinematicLimits nan_turn = diffDrive();
  nan_turn.max_angular_speed = std::nan("");
  refused(nan_turn, 0.1, 0, {}, "max_angular_speed");
  KinematicLimits no_braking = diffDrive();
  no_braking.max_linear_acceleration = 0;
  refused(no_braking, 0.1, 0, {}, "max_linear_acceleration");
  KinematicLimits no_turning = diffDrive();
  no_turning.max_angular_acceleration = -1;
  refused(no_turning, 0.1, 0, {}, "max_angular_acceleration");
  refused(diffDrive(), 0, 0, {}, "control_period");
  refused(diffDrive(), 0.1, -1, {}, "robot_radius");
  DynamicWindowOptions options;
  options.linear_samples = 0;
  refused(diffDrive(), 0.1, 0, options, "linear_samples");
  options = {};
  options.sim_time = -1;
  refused(diffDrive(), 0.1, 0, options, "sim_time");
}

}  // namespace
}  // namespace planners
}  // namespace ppp
