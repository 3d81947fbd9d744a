#include "ppp_agents/astar_agent.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "ppp_agents/episode_runner.hpp"
#include "ppp_core/dpa.hpp"
#include "ppp_core/footprint.hpp"
#include "ppp_core/optimum.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/reachability.hpp"
#include "test_world.hpp"

namespace ppp {
namespace agents {
namespace {

TEST(AstarAgentTest, PassesRandomValidProblemsInTheFewestMoves) {
  struct Size {
    int width, height, obstacles;
  };
  DpaSolver dpa;
  AstarAgent agent;
  int problems = 0;
  for (const Size size : {Size{5, 5, 3}, Size{10, 10, 8}, Size{20, 20, 10}, Size{20, 20, 30}, Size{13, 7, 6},
                          Size{40, 40, 60}}) {
    Rng rng(deriveSeed(11, {static_cast<std::uint64_t>(size.width), static_cast<std::uint64_t>(size.obstacles)}));
    for (int i = 0; i < 60; ++i) {
      Problem shape = Problem::empty(size.width, size.height, size.obstacles);
      if (i % 2 == 1) {  // half of them with a random start and goal
        shape.start = Cell{static_cast<int>(rng.below(size.width)), static_cast<int>(rng.below(size.height))};
        do {
          shape.goal = Cell{static_cast<int>(rng.below(size.width)), static_cast<int>(rng.below(size.height))};
        } while (shape.goal == shape.start);
      }
      const Problem problem = randomProblem(rng, shape, size.obstacles);
      const test::World w{decodeGrid(problem), problem.start, problem.goal};
      const int fewest = stepDistances(w.grid, w.start)[w.grid.index(w.goal)];
      ASSERT_GT(fewest, 0);
      EXPECT_EQ(dpa.solve(w.grid, w.start, w.goal).advances, fewest);
      const auto out = test::runEpisode(agent, w, static_cast<std::uint64_t>(i), 0.0, 10 * fewest + 300, true);
      ASSERT_TRUE(out.passed) << size.width << "x" << size.height << " #" << i;
      EXPECT_EQ(out.steps, fewest) << size.width << "x" << size.height << " #" << i;
      EXPECT_EQ(out.moves, fewest);
      EXPECT_EQ(out.bumps, 0);
      ++problems;
    }
  }
  EXPECT_EQ(problems, 360);
}

TEST(AstarAgentTest, PlansInTheConfigurationSpaceOfTheRobotsBody) {
  // 11x11, a wall across row 3 with a gap two cells wide (x 5-6) and one three wide at the right edge (x 8-10).
  // The point robot takes the near gap; a disc of radius 1 fits only the far one, and astar takes it at once.
  Problem problem = Problem::empty(11, 11, 2);
  problem.start = Cell{1, 1};
  problem.goal = Cell{1, 9};
  problem.obstacles = {Obstacle{Shape::HorizontalBar, 0, 3, 5, 1}, Obstacle{Shape::HorizontalBar, 7, 3, 1, 1}};
  const Grid grid = decodeGrid(problem);
  AgentConfig config;
  config.name = config.type = "astar";
  EpisodeOptions options;
  const int point = recordEpisode(problem, grid, config, options, 1).steps;
  EXPECT_EQ(point, 8 + 2 * 4);  // down 8, across to x 5 and back
  options.robot_radius = 1;
  const EpisodeOutcome body = recordEpisode(problem, grid, config, options, 1);
  EXPECT_TRUE(body.passed);
  EXPECT_EQ(body.bumps, 0);
  EXPECT_EQ(body.steps, 8 + 2 * 8);  // across to x 9 and back
  Grid space;
  EXPECT_EQ(body.steps, optimumOf(problem, motionGrid(grid, 1, &space), Connectivity::Four).moves);
}

TEST(AstarAgentTest, PlanIsAShortestPathAroundWalls) {
  const auto w = test::world({
      "S.#....",
      "..#.##.",
      "..#..#.",
      "....#G.",
  });
  AstarAgent agent;
  std::vector<Action> plan;
  ASSERT_TRUE(agent.plan(w.grid, w.start, w.goal, &plan));
  // Around the wall at x = 2 by row 3, up column 3, over the top and down column 6: 6 + 3 + 3 + 3 + 1 moves.
  EXPECT_EQ(plan.size(), 16u);
  EXPECT_EQ(static_cast<int>(plan.size()), stepDistances(w.grid, w.start)[w.grid.index(w.goal)]);
  Cell c = w.start;
  for (Action a : plan) {
    c = target(c, a);
    ASSERT_TRUE(w.grid.isFree(c));
  }
  EXPECT_EQ(c, w.goal);
  // Deterministic: the same plan every time.
  std::vector<Action> again;
  agent.plan(w.grid, w.start, w.goal, &again);
  EXPECT_EQ(plan, again);
}

TEST(AstarAgentTest, ReplansAfterABumpOnAWrongPriorMap) {
  // The agent believes the map is open; in the real one every shortest path of the open map is blocked.
  const auto real = test::world({
      "S#...",
      ".#.#.",
      "...#G",
  });
  const Grid believed(5, 3);
  AstarAgent agent;
  EpisodeInfo info;
  info.width = 5;
  info.height = 3;
  info.start = real.start;
  info.goal = real.goal;
  info.prior_map = &believed;
  agent.reset(info);
  const SensorModel sensor(SensorOptions{});
  Cell position = real.start;
  bool bumped = false;
  int steps = 0;
  int bumps = 0;
  for (; position != real.goal && steps < 50; ++steps) {
    const Scan scan(sensor, real.grid, position, real.goal, bumped, steps, 0);
    const Cell next = target(position, agent.act(scan));
    bumped = !real.grid.isFree(next);
    if (bumped) {
      ++bumps;
    } else {
      position = next;
    }
  }
  EXPECT_EQ(position, real.goal);
  EXPECT_GE(bumps, 1);
  EXPECT_LT(steps, 50);
}

TEST(AstarAgentTest, StaysPutWhenTheGoalIsUnreachable) {
  const auto w = test::world({
      "S.#.",
      "..#G",
  });
  AstarAgent agent;
  std::vector<Action> plan;
  EXPECT_FALSE(agent.plan(w.grid, w.start, w.goal, &plan));
  const auto out = test::runEpisode(agent, w, 0, 0.0, 20, true);
  EXPECT_FALSE(out.passed);
  EXPECT_EQ(out.moves, 0);
  EXPECT_EQ(out.bumps, 0);
}

}  // namespace
}  // namespace agents
}  // namespace ppp
