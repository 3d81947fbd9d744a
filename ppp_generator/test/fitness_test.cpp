#include "ppp_generator/fitness.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ppp_core/error.hpp"

namespace ppp {
namespace generator {
namespace {

/// 4x4 with one hbar at (1,1) length 2; worked by hand in ppp_core's evaluation_test:
/// 1 turn, 6 advances, 7 together, goal visibility 12/16, difficulty 11.34375.
Problem handProblem() {
  Problem p = Problem::empty(4, 4, 4);
  p.obstacles.push_back(Obstacle{Shape::HorizontalBar, 1, 1, 2, 1});
  return p;
}

double valueOf(const std::string& name, const FitnessParameters& parameters = {}) {
  const Problem p = handProblem();
  const Grid g = decodeGrid(p);
  const DpaResult dpa = solveDpa(g, p.start, p.goal);
  return makeFitness(name, parameters).value(p, g, dpa);
}

TEST(FitnessTest, ValuesMatchTheHandWorkedMeasures) {
  EXPECT_EQ(valueOf("turns"), 1.0);
  EXPECT_EQ(valueOf("advances"), 6.0);
  EXPECT_EQ(valueOf("turns_plus_advances"), 7.0);
  EXPECT_DOUBLE_EQ(valueOf("difficulty"), 11.34375);
  EXPECT_DOUBLE_EQ(valueOf("goal_visibility"), 0.75);
  EXPECT_DOUBLE_EQ(valueOf("visibility_magnitude"), std::sqrt(571.0) / 16);
}

TEST(FitnessTest, DifficultyWeightsReachTheFitness) {
  FitnessParameters p;
  p.weights.one_turn_penalty = 0.0;
  EXPECT_DOUBLE_EQ(valueOf("difficulty", p), 11.34375 - 2.0);
}

TEST(FitnessTest, DirectionsAndScores) {
  EXPECT_TRUE(makeFitness("turns").maximise);
  EXPECT_FALSE(makeFitness("difficulty").maximise);
  EXPECT_FALSE(makeFitness("goal_visibility").maximise);
  EXPECT_EQ(makeFitness("difficulty").score(3.0), -3.0);
  EXPECT_EQ(makeFitness("advances").score(3.0), 3.0);
}

TEST(FitnessTest, RandomIsSeededAndInUnitInterval) {
  FitnessParameters p;
  p.seed = 5;
  const Problem problem = handProblem();
  const Grid g = decodeGrid(problem);
  const DpaResult dpa = solveDpa(g, problem.start, problem.goal);
  Fitness a = makeFitness("random", p), b = makeFitness("random", p);
  for (int i = 0; i < 10; ++i) {
    const double va = a.value(problem, g, dpa);
    EXPECT_EQ(va, b.value(problem, g, dpa));
    EXPECT_GE(va, 0.0);
    EXPECT_LT(va, 1.0);
  }
}

TEST(FitnessTest, UnknownNameListsTheValidOnes) {
  try {
    makeFitness("hardness");
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(std::string(e.what()),
              "fitness: unknown fitness 'hardness'; valid: turns, advances, turns_plus_advances, difficulty, "
              "goal_visibility, visibility_magnitude, random, failure, regret");
  }
  EXPECT_EQ(fitnessCatalogue().size(), 9u);
}

TEST(FitnessTest, FailureIsListedButNeedsAnAgentPanel) {
  EXPECT_TRUE(fitnessMaximises("failure"));
  EXPECT_FALSE(fitnessMaximises("difficulty"));
  EXPECT_THROW(fitnessMaximises("hardness"), InvalidArgument);
  try {
    makeFitness("failure");
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "fitness");
    EXPECT_NE(std::string(e.what()).find("agent panel"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace generator
}  // namespace ppp
