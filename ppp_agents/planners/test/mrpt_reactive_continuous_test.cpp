// MRPT's holonomic reactive methods (ND, VFF, FullEval) on the traps found with one-cell steps, re-judged in
// continuous motion: a diff-drive disc of 0.2 m with heading, velocity and acceleration limits, its 360-beam laser
// turned into how far the disc travels in each of the 72 directions (what MRPT's own navigator gives a holonomic
// method), one method call per 0.1 s control period, for 300 s. Each test says whether the trap survives, and in
// which form; driveReactive() plays mrpt_reactive_node's own steering (ReactiveSteering), without ROS.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ppp_core/episode_reason.hpp"
#include "reactive_drive.hpp"

namespace ppp {
namespace planners {
namespace {

using test::Box;
using test::driveReactive;
using test::lastBox;
using test::pictureProblem;

constexpr double kRadius = test::kTrapRadius;  // metres
constexpr long kPeriods = test::kTrapPeriods;   // 300 s

Problem trapProblem(const std::string& name) { return pictureProblem(test::trapPicture(name)); }

double distance(const Pose2D& pose, double x, double y) { return std::hypot(pose.x - x, pose.y - y); }

// The corner trap survives for VFF and FullEval, in the form the potential field's textbook local minimum takes
// when the robot is not stepped: each comes to rest short of the goal (VFF 0.62 m from its centre, FullEval
// 2.07 m), where on the grid they went back and forth beside it. ND drives in.
TEST(MrptReactiveContinuousTest, VffAndFullEvalComeToRestShortOfAGoalInTheMapsCorner) {
  const Problem corner = trapProblem("corner");
  EXPECT_STREQ(driveReactive(corner, "ND", kRadius, kPeriods).reason, reason::kGoalReached);
  for (const std::string method : {"VFF", "FullEval"}) {
    const ContinuousOutcome outcome = driveReactive(corner, method, kRadius, kPeriods);
    EXPECT_STREQ(outcome.reason, reason::kBudgetExhausted) << method;
    EXPECT_LT(lastBox(outcome).extent(), 0.05) << method << " still moves";
    const double from_goal = distance(outcome.poses.back(), 7.5, 0.5);
    if (method == "VFF") {
      EXPECT_NEAR(from_goal, 0.62, 0.005);
    } else {
      EXPECT_NEAR(from_goal, 2.07, 0.005) << method;
    }
  }
}

// The U facing away from the goal survives for all three: none ever gets round it (the robot's centre never rises
// to the U's closed end, whose inner face is at y = 4 m; leaving by the open end and going round would take it
// above y = 5 m). ND keeps swinging inside (over 0.5 m in its last 100 s), VFF comes to rest, FullEval moves
// about within 0.5 m.
TEST(MrptReactiveContinuousTest, NoMethodGetsRoundAUFacingAwayFromTheGoal) {
  const Problem u = trapProblem("u");
  for (const std::string method : {"ND", "VFF", "FullEval"}) {
    const ContinuousOutcome outcome = driveReactive(u, method, kRadius, kPeriods);
    EXPECT_STREQ(outcome.reason, reason::kBudgetExhausted) << method;
    const auto highest = std::max_element(outcome.poses.begin(), outcome.poses.end(),
                                          [](const Pose2D& a, const Pose2D& b) { return a.y < b.y; });
    EXPECT_LT(highest->y, 4.0) << method;
    const double moved = lastBox(outcome).extent();
    if (method == "ND") {
      EXPECT_GT(moved, 0.5);
    } else {
      EXPECT_LT(moved, method == "VFF" ? 0.05 : 0.5) << method;
    }
  }
}

// The pocket of two diagonal cells survives for VFF: it comes to rest beside the pocket, 1.3 m from the cells'
// shared corner (5, 3). ND and FullEval pass it given the disc's distances; given the nearest ray per sector
// (a point's distances for a body) both collide with the pocket's cells.
TEST(MrptReactiveContinuousTest, VffComesToRestBesideThePocketOfTwoDiagonalCells) {
  const Problem pocket = trapProblem("pocket");
  const ContinuousOutcome vff = driveReactive(pocket, "VFF", kRadius, kPeriods);
  EXPECT_STREQ(vff.reason, reason::kBudgetExhausted);
  EXPECT_LT(lastBox(vff).extent(), 0.05);
  EXPECT_NEAR(distance(vff.poses.back(), 5.0, 3.0), 1.3, 0.05) << "from the cells' shared corner";
  for (const std::string method : {"ND", "FullEval"}) {
    EXPECT_STREQ(driveReactive(pocket, method, kRadius, kPeriods).reason, reason::kGoalReached) << method;
    EXPECT_STREQ(driveReactive(pocket, method, kRadius, kPeriods, kObstaclesFromRays).reason, reason::kCollision)
        << method;
  }
}

// ND's trap of one obstacle cell diagonal to a goal in the corner survives as it was: for its last 100 s the
// robot swings (over 0.5 m) west and north-west of the cell (x in [4, 5] m, y in [1, 2] m) and never passes it.
// VFF and FullEval stop near the cell, moving less than 0.1 m in their last 100 s.
TEST(MrptReactiveContinuousTest, NdStillSwingsBesideOneObstacleBeforeAGoalInTheCorner) {
  const Problem one_cell = trapProblem("one_cell");
  for (const std::string method : {"VFF", "FullEval"}) {
    const ContinuousOutcome outcome = driveReactive(one_cell, method, kRadius, kPeriods);
    EXPECT_STREQ(outcome.reason, reason::kBudgetExhausted) << method;
    EXPECT_LT(lastBox(outcome).extent(), 0.1) << method;
    EXPECT_LT(distance(outcome.poses.back(), 4.5, 1.5), 2.0) << method;
  }
  const ContinuousOutcome nd = driveReactive(one_cell, "ND", kRadius, kPeriods);
  EXPECT_STREQ(nd.reason, reason::kBudgetExhausted);
  const Box box = lastBox(nd);
  EXPECT_GT(box.extent(), 0.5);
  EXPECT_GE(box.x0, 2.5);
  EXPECT_LT(box.x1, 4.0);
  EXPECT_GE(box.y0, 1.5);
  EXPECT_LT(box.y1, 3.5);
}

}  // namespace
}  // namespace planners
}  // namespace ppp
