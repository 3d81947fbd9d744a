// The DWA example's planning without ROS (DwaPlanner, what dwa_planner_node runs): driving a diff-drive robot in
// continuous motion, from the laser alone, it reaches the goal of an open map and of one with a wall to go round,
// never touching a square; asked before an episode or with a goal that is not finite it says so.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "dwa_planner.hpp"
#include "ppp_core/continuous_episode.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/problem.hpp"

namespace ppp {
namespace planners {
namespace {

DwaNodeParameters diffDrive() {
  DwaNodeParameters parameters;
  parameters.kinematics = kKinematicsDiffDrive;
  return parameters;
}

/// Plays `problem` in continuous motion (defaults: a diff-drive point robot, 1 m cells) with a DwaPlanner.
ContinuousOutcome drive(const Problem& problem) {
  const Grid grid = decodeGrid(problem);
  MotionOptions options;
  options.motion = kMotionContinuous;
  ContinuousEpisode episode(problem, grid, options, 0, 2000, 1);
  DwaPlanner planner(diffDrive());
  planner.newEpisode(problem.width * options.resolution, problem.height * options.resolution, MapPoint{0, 0});
  const LaserBeams& beams = episode.beams();
  std::vector<float> ranges;
  while (!episode.done()) {
    episode.scan(&ranges);
    DwaRequest request;
    request.pose = episode.pose();
    request.velocity = episode.velocity();
    request.goal = episode.goal();
    request.scan = LaserReadings{&ranges, beams.angle_min, beams.angle_increment, 0, beams.range_max};
    episode.apply(planner.command(request));
  }
  return episode.outcome();
}

TEST(DwaPlannerTest, DrivesAcrossAnOpenMapToTheGoal) {
  const ContinuousOutcome outcome = drive(Problem::empty(6, 6, 2));
  EXPECT_TRUE(outcome.passed) << outcome.reason << " after " << outcome.steps << " periods";
}

TEST(DwaPlannerTest, GoesRoundAWallItSeesOnlyByItsLaser) {
  // A wall down the middle of an 8x8 map, open at the bottom: the start is top-left, the goal bottom-right.
  Problem problem = Problem::empty(8, 8, 2);
  problem.obstacles.push_back(Obstacle{Shape::VerticalBar, 4, 0, 6, 1});
  const ContinuousOutcome outcome = drive(problem);
  EXPECT_TRUE(outcome.passed) << outcome.reason << " after " << outcome.steps << " periods";
}

TEST(DwaPlannerTest, RefusesARequestBeforeAnEpisodeAndAGoalThatIsNotFinite) {
  DwaPlanner planner(diffDrive());
  const std::vector<float> ranges;
  DwaRequest request;
  request.scan.ranges = &ranges;
  EXPECT_THROW(planner.command(request), std::logic_error);
  planner.newEpisode(4, 4, MapPoint{0, 0});
  request.goal = MapPoint{std::numeric_limits<double>::quiet_NaN(), 1};
  try {
    planner.command(request);
    FAIL() << "a NaN goal was answered";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "goal");
  }
}

}  // namespace
}  // namespace planners
}  // namespace ppp
