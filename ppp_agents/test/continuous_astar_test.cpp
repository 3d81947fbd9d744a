// The control in continuous motion: A* on the disc's configuration space followed by pure pursuit reaches the
// goal of every PPP solvable for its disc, for both kinematics; agents that move only on the grid are refused.

#include "ppp_agents/continuous/continuous_runner.hpp"

#include <gtest/gtest.h>

#include <string>

#include "ppp_agents/episode_runner.hpp"
#include "ppp_core/episode_reason.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/reachability.hpp"
#include "ppp_core/square_world.hpp"

namespace ppp {
namespace agents {
namespace {

AgentConfig astar() {
  AgentConfig config;
  config.name = config.type = "astar";
  return config;
}

TEST(ContinuousAstarTest, PassesEveryPppSolvableForItsDisc) {
  Rng rng(11);
  int solvable = 0;
  for (int map = 0; map < 30; ++map) {
    const Problem problem = randomProblem(rng, Problem::empty(20, 20, 12), 12);
    const Grid grid = decodeGrid(problem);
    const int grid_moves = fewestMoves(grid, problem.start, problem.goal, Connectivity::Four);
    for (const char* kinematics : {kKinematicsDiffDrive, kKinematicsHolonomic}) {
      for (const double radius : {0.0, 0.2, 0.35, 0.45, 0.49}) {
        EpisodeOptions options;
        options.motion.motion = kMotionContinuous;
        options.motion.kinematics = kinematics;
        options.robot_radius = radius;
        const SquareWorld world(grid, options.motion.resolution);
        const Grid space = continuousConfigurationSpace(world, radius);
        if (!space.isFree(problem.start) || !isReachable(space, problem.start, problem.goal)) continue;
        ++solvable;
        ContinuousRunner runner(astar(), options);
        const ContinuousOutcome outcome = runner.run(problem, grid, grid_moves, 1);
        EXPECT_TRUE(outcome.passed) << "map " << map << ", " << kinematics << ", radius " << radius << ": "
                                    << outcome.reason << " after " << outcome.steps << " periods";
      }
    }
  }
  EXPECT_GT(solvable, 250);  // most of the 300 cases: the test is not vacuous
}

TEST(ContinuousAstarTest, PassesUnderOtherCellSizesSpeedsAndControlPeriods) {
  // Small cells, a fast robot that accelerates slowly, and long control periods: braking must still stop it at
  // each turn of a route with a disc of 0.45 cells.
  Rng rng(12);
  EpisodeOptions options;
  options.motion.motion = kMotionContinuous;
  options.motion.resolution = 0.25;
  options.motion.max_linear_speed = 2;
  options.motion.max_linear_acceleration = 0.5;
  options.motion.control_period = 0.2;
  options.motion.time_factor = 50;  // stopping at every turn, it seldom reaches its top speed
  options.robot_radius = 0.45;
  for (const char* kinematics : {kKinematicsDiffDrive, kKinematicsHolonomic}) {
    options.motion.kinematics = kinematics;
    for (int map = 0; map < 10; ++map) {
      const Problem problem = randomProblem(rng, Problem::empty(20, 20, 12), 12);
      const Grid grid = decodeGrid(problem);
      ContinuousRunner runner(astar(), options);
      const ContinuousOutcome outcome =
          runner.run(problem, grid, fewestMoves(grid, problem.start, problem.goal, Connectivity::Four), 1);
      EXPECT_TRUE(outcome.passed) << "map " << map << ", " << kinematics << ": " << outcome.reason;
    }
  }
}

TEST(ContinuousAstarTest, ItsRunsAreReproducibleAndItsRowsInCells) {
  Rng rng(5);
  const Problem problem = randomProblem(rng, Problem::empty(20, 20, 10), 10);
  const Grid grid = decodeGrid(problem);
  EpisodeOptions options;
  options.motion.motion = kMotionContinuous;
  options.robot_radius = 0.2;
  const int grid_moves = fewestMoves(grid, problem.start, problem.goal, Connectivity::Four);
  ContinuousRunner first(astar(), options), second(astar(), options);
  const ContinuousOutcome a = first.run(problem, grid, grid_moves, 3, true);
  const ContinuousOutcome b = second.run(problem, grid, grid_moves, 3, true);
  ASSERT_EQ(a.poses.size(), b.poses.size());
  EXPECT_EQ(a.poses.size(), a.cells.size());
  EXPECT_EQ(a.poses.back().x, b.poses.back().x);
  EXPECT_EQ(a.distance, b.distance);
  // Cutting corners, the route is no longer than the 4-connected one, and not shorter than the straight line.
  const double straight = std::hypot(problem.goal.x - problem.start.x, problem.goal.y - problem.start.y);
  EXPECT_LE(a.distance, grid_moves * options.motion.resolution + 1e-9);
  EXPECT_GE(a.distance, straight - options.motion.goal_tolerance);
}

TEST(ContinuousAgentTest, AgentsThatMoveOnlyOnTheGridAreRefusedNamingTheAgentAndTheOption) {
  EpisodeOptions options;
  options.motion.motion = kMotionContinuous;
  AgentConfig explorer;
  explorer.name = "my_explorer";
  explorer.type = "explorer";
  try {
    checkContinuousAgent(explorer, options);
    FAIL() << "an explorer was accepted in continuous motion";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "motion");
    EXPECT_NE(std::string(e.what()).find("my_explorer"), std::string::npos) << e.what();
  }
  explorer.motion = kMotionGrid;  // its own motion model overrides the experiment's
  EXPECT_NO_THROW(checkContinuousAgent(explorer, options));
  EXPECT_NO_THROW(EpisodeRunner(explorer, options));
  // The grid runner never plays a continuous run as a grid one.
  EXPECT_THROW(EpisodeRunner(astar(), options), InvalidArgument);
}

}  // namespace
}  // namespace agents
}  // namespace ppp
