// mrpt_reactive_node's steering without ROS (ReactiveSteering): the goal's frame keeps ND's seam away from the goal,
// and bad input is refused naming what is wrong.
#include "reactive_steering.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"

namespace ppp {
namespace planners {
namespace {

constexpr float kNoReturn = std::numeric_limits<float>::infinity();

ReactiveNodeParameters ndIn(const std::string& frame) {
  ReactiveNodeParameters parameters;
  parameters.method = "ND";
  parameters.frame = frame;
  parameters.kinematics = kKinematicsHolonomic;
  return parameters;
}

/// Degrees between ND's choice and an open goal 1 m away in the direction of sector k, nothing within range.
double offGoal(const std::string& frame, int k) {
  ReactiveSteering steering(ndIn(frame));
  const LaserRays scan{-M_PI, 2 * M_PI / 360, std::vector<float>(360, kNoReturn)};
  ReactiveView view;
  view.goal = MapPoint{std::cos(sectorAngle(k)), std::sin(sectorAngle(k))};
  view.range = 2.0;
  view.scan = &scan;
  int invalid = 0;
  const Heading choice = steering.steer(view, &invalid);
  return std::abs(std::remainder(choice.direction - sectorAngle(k), 2 * M_PI)) * 180 / M_PI;
}

// In the robot's frame ND turns 35-45 degrees away from an open goal within two sectors of its seam (sectors 0-2 and
// 70-71, mrpt_reactive_navigator_test); counted from the goal's direction the seam is always behind, 177.5 degrees
// from the goal, and ND heads for it in all 72 directions.
TEST(ReactiveSteeringTest, InTheGoalsFrameNdHeadsForAnOpenGoalInEveryDirection) {
  int turned_away_in_robot_frame = 0;
  for (int k = 0; k < kReactiveSectors; ++k) {
    EXPECT_LT(offGoal(kReactiveFrameGoal, k), 1e-6) << "sector " << k;
    if (offGoal(kReactiveFrameRobot, k) > 30) ++turned_away_in_robot_frame;
  }
  EXPECT_EQ(turned_away_in_robot_frame, 5);
}

// In the goal's frame the method's input depends only on the scene as seen from the goal's direction: turning the
// whole scene (the scan's returns and the goal) by any angle turns ND's choice by that angle and changes nothing
// else, for a point (nearest rays) and for a disc. A wall of returns 0.8 m away stands across the way to a goal
// 1.5 m off, so ND has to choose a side.
TEST(ReactiveSteeringTest, InTheGoalsFrameTurningTheSceneTurnsTheChoice) {
  for (const double radius : {0.0, 0.2}) {
    std::vector<float> wall(360, kNoReturn);
    for (int i = -30; i <= 10; ++i) wall[static_cast<std::size_t>((i + 360) % 360)] = 0.8f / std::cos(i * M_PI / 180);
    std::vector<Heading> choices;
    for (const double angle : {0.0, 1.0, -2.5}) {
      ReactiveNodeParameters parameters = ndIn(kReactiveFrameGoal);
      parameters.robot_radius = radius;
      ReactiveSteering steering(parameters);
      const LaserRays scan{angle, 2 * M_PI / 360, wall};  // ray 0 along `angle`
      ReactiveView view;
      view.goal = MapPoint{1.5 * std::cos(angle + 0.1), 1.5 * std::sin(angle + 0.1)};
      view.range = 2.0;
      view.scan = &scan;
      int invalid = 0;
      Heading choice = steering.steer(view, &invalid);
      choice.direction = std::remainder(choice.direction - angle, 2 * M_PI);
      choices.push_back(choice);
    }
    EXPECT_GT(std::abs(choices[0].direction - 0.1), 0.3) << "radius " << radius << ": ND went through the wall";
    for (const Heading& choice : choices) {
      EXPECT_NEAR(choice.direction, choices[0].direction, 1e-9) << "radius " << radius;
      EXPECT_NEAR(choice.speed, choices[0].speed, 1e-9) << "radius " << radius;
    }
  }
}

TEST(ReactiveSteeringTest, BadInputIsRefusedNamingIt) {
  ReactiveNodeParameters bad = ndIn("map");
  try {
    ReactiveSteering steering(bad);
    FAIL() << "accepted frame map";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "frame");
  }
  ReactiveSteering steering(ndIn(kReactiveFrameRobot));
  const LaserRays scan{0, 2 * M_PI / 360, std::vector<float>(360, kNoReturn)};
  ReactiveView view;
  view.goal = MapPoint{std::numeric_limits<double>::quiet_NaN(), 1.0};
  view.range = 2.0;
  view.scan = &scan;
  int invalid = 0;
  try {
    steering.steer(view, &invalid);
    FAIL() << "accepted a goal that is not finite";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "goal");
  }
  view.goal = MapPoint{1.0, 1.0};
  const LaserRays nowhere{0, 0, std::vector<float>(360, kNoReturn)};
  view.scan = &nowhere;
  try {
    steering.steer(view, &invalid);
    FAIL() << "accepted rays with no angle between them";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "scan");
  }
  ReactiveNodeParameters memory = ndIn(kReactiveFrameRobot);
  memory.obstacles = kObstaclesFromMemory;
  ReactiveSteering from_memory(memory);
  try {
    from_memory.steer(view, &invalid);
    FAIL() << "cast on no map";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "map");
  }
}

}  // namespace
}  // namespace planners
}  // namespace ppp
