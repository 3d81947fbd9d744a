#include "ppp_core/evaluation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ppp_core/error.hpp"
#include "ppp_core/openness.hpp"

namespace ppp {
namespace {

/// 4x4, obstacles (1,1) and (2,1) from one hbar, budget 4:
///   S...
///   .##.
///   ....
///   ...G
Problem handProblem() {
  Problem p = Problem::empty(4, 4, 4);
  p.obstacles.push_back(Obstacle{Shape::HorizontalBar, 1, 1, 2, 1});
  return p;
}

TEST(EvaluationTest, OpennessWorkedByHand) {
  const Grid g = decodeGrid(handProblem());
  // Rows: longest free runs 4, 1, 4, 4 -> (1 + 0.25 + 1 + 1) / 4.
  EXPECT_DOUBLE_EQ(horizontalOpenness(g), 0.8125);
  // Columns: 4, 2, 2, 4 -> (1 + 0.5 + 0.5 + 1) / 4.
  EXPECT_DOUBLE_EQ(verticalOpenness(g), 0.75);
}

TEST(EvaluationTest, DifficultyWorkedByHand) {
  // Visible cells counted by hand with the shadow rule (see docs/reference/evaluation.md):
  // start (0,0) 9, goal (3,3) 12, centre (2,2) 11, top-right (3,0) 9, bottom-left (0,3) 12, of 16.
  Evaluator evaluator;
  const Evaluation e = evaluator.evaluate(handProblem());
  ASSERT_TRUE(e.valid);
  EXPECT_EQ(e.turns, 1);
  EXPECT_EQ(e.advances, 6);
  EXPECT_EQ(e.turns_plus_advances, 7);
  EXPECT_EQ(e.obstacles, 1);
  EXPECT_DOUBLE_EQ(e.obstacle_use, 0.25);
  EXPECT_DOUBLE_EQ(e.visibility.start, 9.0 / 16);
  EXPECT_DOUBLE_EQ(e.visibility.goal, 12.0 / 16);
  EXPECT_DOUBLE_EQ(e.visibility.centre, 11.0 / 16);
  EXPECT_DOUBLE_EQ(e.visibility.top_right, 9.0 / 16);
  EXPECT_DOUBLE_EQ(e.visibility.bottom_left, 12.0 / 16);
  // 1.5*9/16 + 11/16 + 9/16 + 12/16 + 2.5*12/16 = 75.5/16.
  EXPECT_DOUBLE_EQ(e.visibility_function, 75.5 / 16);
  // + 2*(1 - 0.25) + 2*0.8125 + 2*0.75 + 2 (one turn) = 11.34375.
  EXPECT_DOUBLE_EQ(e.difficulty, 11.34375);
  EXPECT_DOUBLE_EQ(e.goal_visibility, 0.75);
  EXPECT_DOUBLE_EQ(e.visibility_magnitude, std::sqrt(571.0) / 16);
}

TEST(EvaluationTest, EveryWeightIsAParameter) {
  DifficultyWeights w;
  w.start = w.centre = w.top_right = w.bottom_left = w.goal = 1.0;
  w.unused_obstacles = w.horizontal_openness = w.vertical_openness = 1.0;
  w.one_turn_penalty = 0.0;
  Evaluator evaluator(w);
  // 53/16 + 0.75 + 0.8125 + 0.75 + 0.
  EXPECT_DOUBLE_EQ(evaluator.evaluate(handProblem()).difficulty, 5.625);
  w.goal = std::nan("");
  EXPECT_THROW(Evaluator{w}, InvalidArgument);
}

TEST(EvaluationTest, CharacterVectorFollowsTheNames) {
  Evaluator evaluator;
  const Evaluation e = evaluator.evaluate(handProblem());
  const auto values = characterVector(e);
  ASSERT_EQ(values.size(), characterNames().size());
  EXPECT_EQ(characterNames()[0], "turns");
  EXPECT_EQ(values[0], 1.0);
  EXPECT_EQ(characterNames()[3], "obstacles");
  EXPECT_EQ(values[3], 1.0);
  EXPECT_EQ(characterNames()[12], "one_turn");
  EXPECT_EQ(values[12], 1.0);
  EXPECT_EQ(characterNames().back(), "difficulty");
  EXPECT_DOUBLE_EQ(values.back(), 11.34375);
}

TEST(EvaluationTest, UnreachableGoalIsInvalid) {
  Problem p = Problem::empty(4, 4, 2);
  p.obstacles.push_back(Obstacle{Shape::DiagonalUp, 0, 3, 4, 1});
  Evaluator evaluator;
  const Evaluation e = evaluator.evaluate(p);
  EXPECT_FALSE(e.valid);
  EXPECT_EQ(e.turns, -1);
}

}  // namespace
}  // namespace ppp
