// The agents' rules step by step, on received scans and small drawn maps.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_agents/bumper_agent.hpp"
#include "ppp_agents/explorer_agent.hpp"
#include "ppp_agents/random_agent.hpp"
#include "ppp_agents/wall_follower_agent.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/random_problem.hpp"
#include "test_world.hpp"

namespace ppp {
namespace agents {
namespace {

EpisodeInfo info(int width, int height, Cell start, Cell goal, std::uint64_t seed) {
  EpisodeInfo i;
  i.width = width;
  i.height = height;
  i.start = start;
  i.goal = goal;
  i.seed = seed;
  return i;
}

/// A received range-2 scan whose 25 cells all hold `value` (the agent's own cell free).
Scan uniformScan(std::int8_t value, Cell position, Cell goal, bool bumped, int step) {
  std::vector<std::int8_t> cells(25, value);
  cells[12] = kScanFree;
  return Scan(2, cells, position, goal, bumped, step);
}

TEST(AgentBehaviourTest, RandomIgnoresTheScanAndUsesAllFiveActions) {
  RandomAgent a;
  RandomAgent b;
  a.reset(info(20, 20, Cell{0, 0}, Cell{1, 1}, 42));
  b.reset(info(20, 20, Cell{0, 0}, Cell{1, 1}, 42));
  std::set<Action> seen;
  for (int step = 0; step < 200; ++step) {
    // Same seed, entirely different scans (one even shows the goal next to it): the same actions.
    const Action x = a.act(uniformScan(kScanObstacle, Cell{5, 5}, Cell{19, 19}, step % 2 == 0, step));
    const Action y = b.act(uniformScan(kScanFree, Cell{step % 20, 3}, Cell{step % 20 + 1, 3}, false, step));
    ASSERT_EQ(x, y) << step;
    seen.insert(x);
  }
  EXPECT_EQ(seen.size(), 5u);
}

TEST(AgentBehaviourTest, BumperGoesStraightUntilABumpThenTurnsToAnotherDirection) {
  BumperAgent bumper(false, AgentBehaviour{});
  for (std::uint64_t seed = 0; seed < 30; ++seed) {
    bumper.reset(info(50, 50, Cell{25, 25}, Cell{0, 0}, seed));
    const Action first = bumper.act(uniformScan(kScanFree, Cell{25, 25}, Cell{0, 0}, false, 0));
    ASSERT_NE(first, Action::Stay);
    for (int step = 1; step < 10; ++step) {
      // The window's contents never matter while the goal is out of it: all-obstacle scans, same straight line.
      ASSERT_EQ(bumper.act(uniformScan(kScanObstacle, Cell{25, 25}, Cell{0, 0}, false, step)), first);
    }
    const Action turned = bumper.act(uniformScan(kScanFree, Cell{25, 25}, Cell{0, 0}, true, 10));
    EXPECT_NE(turned, first);
    EXPECT_NE(turned, Action::Stay);
    EXPECT_EQ(bumper.act(uniformScan(kScanFree, Cell{25, 25}, Cell{0, 0}, false, 11)), turned);
  }
}

TEST(AgentBehaviourTest, DecisionBumperTriesEveryDirectionAtACellBeforeRepeatingOne) {
  // Bumping again and again at the same cell: decision_bumper's first four directions are all different;
  // the plain bumper only avoids the direction it just bumped in, so some seeds repeat one.
  int bumper_repeats = 0;
  for (bool decision : {true, false}) {
    BumperAgent agent(decision, AgentBehaviour{});
    for (std::uint64_t seed = 0; seed < 100; ++seed) {
      agent.reset(info(9, 9, Cell{4, 4}, Cell{0, 0}, seed));
      std::vector<Action> directions;
      for (int step = 0; step < 4; ++step) {
        directions.push_back(agent.act(uniformScan(kScanFree, Cell{4, 4}, Cell{0, 0}, step > 0, step)));
      }
      const std::set<Action> distinct(directions.begin(), directions.end());
      if (decision) {
        EXPECT_EQ(distinct.size(), 4u) << seed;
      } else {
        bumper_repeats += distinct.size() < 4 ? 1 : 0;
      }
      for (int i = 1; i < 4; ++i) EXPECT_NE(directions[i], directions[i - 1]);
    }
  }
  // Three consecutive turns, each uniform over three directions, use all four with probability 2/9 only.
  std::printf("[ measured ] bumper repeated a direction within its first four in %d of 100 seeds\n", bumper_repeats);
  EXPECT_GT(bumper_repeats, 50);
}

TEST(AgentBehaviourTest, QuarterTurnBumpersTurnLeftOrRightAndTheDecisionBumperGoesRoundTheCompass) {
  // Bumping again and again at the same cell with bumper_turn: quarter. The bumper's new direction is always a
  // quarter turn from the one that bumped, left for some seeds and right for others. The decision bumper's is
  // too, and derived by hand: after d and its quarter turn p, the only untried quarter turn of p is d's reverse,
  // and then of that the other quarter turn of d: it tries all four, d, p, -d, -p.
  AgentBehaviour quarter;
  quarter.quarter_turns = true;
  const auto index = [](Action a) { return static_cast<int>(a) - 1; };
  for (bool decision : {false, true}) {
    BumperAgent agent(decision, quarter);
    std::set<int> turns_seen;
    for (std::uint64_t seed = 0; seed < 60; ++seed) {
      agent.reset(info(9, 9, Cell{4, 4}, Cell{0, 0}, seed));
      std::vector<int> directions;
      for (int step = 0; step < 4; ++step) {
        directions.push_back(index(agent.act(uniformScan(kScanFree, Cell{4, 4}, Cell{0, 0}, step > 0, step))));
      }
      for (int i = 1; i < 4; ++i) {
        const int turn = (directions[i] - directions[i - 1] + 4) % 4;
        EXPECT_TRUE(turn == 1 || turn == 3) << seed;
        turns_seen.insert(turn);
      }
      if (decision) {
        EXPECT_EQ(directions[2], (directions[0] + 2) % 4) << seed;
        EXPECT_EQ(directions[3], (directions[1] + 2) % 4) << seed;
      }
    }
    EXPECT_EQ(turns_seen, (std::set<int>{1, 3})) << decision;
  }
}

TEST(AgentBehaviourTest, WallFollowersKeepTheWallOnTheirSide) {
  const test::World w = test::world({
      "....#.......",
      ".S..#.......",
      "....#.......",
      "....#.......",
      "............",
      "............",
      "............",
      "...........G",
  });
  // Heading east (the goal's larger difference) until the wall at x = 4, then the left follower turns right
  // to keep it on its left: down its west face, round its end and up its east face, then east along the edge.
  WallFollowerAgent left(WallFollowerAgent::Side::Left, AgentBehaviour{});
  const auto l = test::runEpisode(left, w, 0, 0.0, 13);
  const std::vector<Cell> expected_left = {{1, 1}, {2, 1}, {3, 1}, {3, 2}, {3, 3}, {3, 4}, {4, 4},
                                           {5, 4}, {5, 3}, {5, 2}, {5, 1}, {5, 0}, {6, 0}, {7, 0}};
  EXPECT_EQ(l.path, expected_left);
  // The right follower turns left at the wall: up to the top edge, west along it, down the west edge.
  WallFollowerAgent right(WallFollowerAgent::Side::Right, AgentBehaviour{});
  const auto r = test::runEpisode(right, w, 0, 0.0, 9);
  const std::vector<Cell> expected_right = {{1, 1}, {2, 1}, {3, 1}, {3, 0}, {2, 0},
                                            {1, 0}, {0, 0}, {0, 1}, {0, 2}, {0, 3}};
  EXPECT_EQ(r.path, expected_right);
  // Both get there in the end: the goal lies on the loop they follow (the map's edge).
  EXPECT_TRUE(test::runEpisode(left, w, 0).passed);
  EXPECT_TRUE(test::runEpisode(right, w, 0).passed);
  // By touch the left follower walks the same cells, bumping where the scan told the other one of a wall: into the
  // wall at (4,1), (4,2) and (4,3) (the first one starts the following), at (4,4) into (4,3) before going on east,
  // up the east face into (4,3), (4,2), (4,1) and (4,0), at (5,0) off the top edge ahead, then at (6,0) off the
  // edge on its left: 13 moves and 10 bumps in 23 actions.
  AgentBehaviour touch;
  touch.walls_by_touch = true;
  WallFollowerAgent left_by_touch(WallFollowerAgent::Side::Left, touch);
  const auto t = test::runEpisode(left_by_touch, w, 0, 0.0, 23);
  EXPECT_EQ(t.path, expected_left);
  EXPECT_EQ(t.bumps, 10);
  EXPECT_TRUE(test::runEpisode(left_by_touch, w, 0).passed);
}

TEST(AgentBehaviourTest, ExplorerMovesTowardsTheUnknown) {
  // In a corridor explored behind it the explorer keeps moving east, where the unknown cells are.
  const test::World w = test::world({
      "##############",
      "S............G",
      "##############",
  });
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    for (bool long_term : {false, true}) {
      ExplorerAgent agent(long_term, AgentBehaviour{});
      const auto out = test::runEpisode(agent, w, seed);
      EXPECT_TRUE(out.passed);
      EXPECT_EQ(out.moves, 13) << long_term;
    }
  }
}

TEST(AgentBehaviourTest, LongTermExplorerGoesBackForTheNearestFrontier) {
  // A corridor whose east end is a dead end; the way on is a side branch at its west end, out of sight from the
  // east end. Once the east end is explored there is nothing new near: the long-term explorer walks straight
  // back to the frontier at the branch (no random wandering), and finds the goal.
  const test::World w = test::world({
      "#.##########",
      "#S.........#",
      "#.##########",
      "#.##########",
      "#.##########",
      "#G##########",
  });
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    ExplorerAgent agent(true, AgentBehaviour{});
    const auto out = test::runEpisode(agent, w, seed);
    EXPECT_TRUE(out.passed) << seed;
    EXPECT_LE(out.moves, 2 * 9 + 4) << seed;  // at worst: east to the end and back, then down the branch
  }
}

TEST(AgentBehaviourTest, AGoalDirectedLongTermExplorerWalksToTheFrontierOnTheGoalsSide) {
  // A corridor with a branch down at each end, the goal at the foot of the east one. Scans from x = 3..11 along the
  // corridor, then from (5,1): its whole length is known and nothing new is in reach (the cells below are behind
  // walls), so the explorer walks to a frontier. The west branch is 5 steps away (and 14 more to the goal), the
  // east one at least 8 (and at most 3 more): the nearest is West, the goal-directed choice East.
  const test::World w = test::world({
      "###############",
      "#....S........#",
      "#.###########.#",
      "#.###########.#",
      "#.###########G#",
  });
  const SensorModel sensor(SensorOptions{2, 0.0});
  for (const std::string& frontier : {kFrontierNearest, kFrontierGoal}) {
    AgentConfig config = test::config("long_term_explorer");
    config.goal_seeking = kGoalSeekingOff;
    config.frontier = frontier;
    auto agent = makeAgent(config);
    agent->reset(info(15, 5, w.start, w.goal, 1));
    int step = 0;
    for (int x = 3; x <= 11; ++x) agent->act(Scan(sensor, w.grid, Cell{x, 1}, w.goal, false, step++, 0));
    const Action action = agent->act(Scan(sensor, w.grid, Cell{5, 1}, w.goal, false, step++, 0));
    EXPECT_EQ(action, frontier == std::string(kFrontierGoal) ? Action::East : Action::West) << frontier;
  }
}

TEST(AgentBehaviourTest, GoalSeekingChangesNothingBeforeTheGoalComesIntoView) {
  // Each seeking type with goal seeking off, and random with it on, against its type's design on the same seeds:
  // the walks agree until the agent first stands within sensor range of the goal (a necessary condition for
  // seeing it), and seeking passes more runs in all.
  for (const std::string& type : {"random", "wall_follower_left", "wall_follower_right", "explorer",
                                  "long_term_explorer", "bumper", "decision_bumper"}) {
    AgentConfig changed = test::config(type);
    changed.goal_seeking = type == std::string("random") ? kGoalSeekingOn : kGoalSeekingOff;
    auto by_type = makeAgent(test::config(type));
    auto other = makeAgent(changed);
    int seeker_passes = 0;
    int strategy_passes = 0;
    Rng rng(deriveSeed(31, {nameHash(type)}));
    for (int i = 0; i < 150; ++i) {
      const Problem problem = randomProblem(rng, Problem::empty(12, 12, 6), 6);
      const test::World w{decodeGrid(problem), problem.start, problem.goal};
      const std::uint64_t seed = rng.next();
      const auto a = test::runEpisode(*by_type, w, seed, 0.0, 150);
      const auto b = test::runEpisode(*other, w, seed, 0.0, 150);
      std::size_t first_in_range = 0;
      while (first_in_range < a.path.size() && std::max(std::abs(a.path[first_in_range].x - w.goal.x),
                                                        std::abs(a.path[first_in_range].y - w.goal.y)) > 2) {
        ++first_in_range;
      }
      for (std::size_t k = 0; k <= first_in_range && k < a.path.size() && k < b.path.size(); ++k) {
        ASSERT_EQ(a.path[k], b.path[k]) << type << " run " << i << " cell " << k;
      }
      const bool seeker_is_a = type != std::string("random");
      seeker_passes += (seeker_is_a ? a : b).passed ? 1 : 0;
      strategy_passes += (seeker_is_a ? b : a).passed ? 1 : 0;
    }
    std::printf("[ measured ] %s: %d of 150 passed seeking the goal, %d without\n", type.c_str(), seeker_passes,
                strategy_passes);
    EXPECT_GT(seeker_passes, strategy_passes) << type;
  }
}

TEST(AgentBehaviourTest, AWallFollowerByTouchResumesFromTheWallSideWhenTheGoalTurnsOutWalledIn) {
  // Scans fed by hand to a left follower by touch noticing the goal within 2 cells. At (8,4) it heads West for the
  // goal; bumping there it faces North with the wall on its left and tries straight on, and bumping again it tries
  // away from the wall, East. From (6,2), (4,0) and (4,4) it notices the goal and heads for it; from (2,2) its
  // memory shows the goal walled in, so it follows the wall again: from its wall side (West, as it faces North), not
  // from where the bumps left off (East).
  const test::World w = test::world({
      ".........",
      "....#....",
      "...#G#...",
      "....#....",
      "........S",
  });
  const SensorModel sensor(SensorOptions{2, 0.0});
  AgentBehaviour touch;
  touch.walls_by_touch = true;
  touch.goal_range = 2;
  WallFollowerAgent left(WallFollowerAgent::Side::Left, touch);
  left.reset(info(9, 5, w.start, w.goal, 1));
  int step = 0;
  const auto act = [&](Cell at, bool bumped) { return left.act(Scan(sensor, w.grid, at, w.goal, bumped, step++, 0)); };
  EXPECT_EQ(act(Cell{8, 4}, false), Action::West);
  EXPECT_EQ(act(Cell{8, 4}, true), Action::North);
  EXPECT_EQ(act(Cell{8, 4}, true), Action::East);
  for (const Cell noticed : {Cell{6, 2}, Cell{4, 0}, Cell{4, 4}}) act(noticed, false);
  EXPECT_EQ(act(Cell{2, 2}, false), Action::West);
}

TEST(AgentBehaviourTest, ARandomWallStartDrawsTheFirstHeadingFromTheSeed) {
  // From the centre of an open 9x9 map, the goal out of view: heading for the goal is always East first (the
  // axes tie); a random wall start goes each of the four ways for some seed, the same way for the same seed.
  const test::World w = test::world({".........", ".........", ".........", ".........", "....S....", ".........",
                                     ".........", ".........", "........G"});
  for (const std::string& type : {"wall_follower_left", "wall_follower_right"}) {
    AgentConfig random_start = test::config(type);
    random_start.wall_start = kWallStartRandom;
    auto by_goal = makeAgent(test::config(type));
    auto by_draw = makeAgent(random_start);
    std::set<std::pair<int, int>> first_cells;
    for (std::uint64_t seed = 0; seed < 40; ++seed) {
      EXPECT_EQ(test::runEpisode(*by_goal, w, seed, 0.0, 1).path.back(), (Cell{5, 4})) << type;
      const auto drawn = test::runEpisode(*by_draw, w, seed, 0.0, 3);
      EXPECT_EQ(drawn.path, test::runEpisode(*by_draw, w, seed, 0.0, 3).path) << type;
      ASSERT_EQ(drawn.path.size(), 4u) << type;  // straight on: three moves, no wall met
      EXPECT_EQ(drawn.path[3].x - drawn.path[0].x, 3 * (drawn.path[1].x - drawn.path[0].x)) << type;
      EXPECT_EQ(drawn.path[3].y - drawn.path[0].y, 3 * (drawn.path[1].y - drawn.path[0].y)) << type;
      first_cells.insert({drawn.path[1].x, drawn.path[1].y});
    }
    EXPECT_EQ(first_cells.size(), 4u) << type;
  }
}

TEST(AgentBehaviourTest, AWallFollowerThatLetsGoOfTheWallDependsOnItsHand) {
  // Goal seeking off, so only the wall rule plays. Both hands walk the staircase (1, 0), (1, 1), (2, 1) and meet
  // the one-cell island at (2, 2) moving South. Never letting go, each circles it for good (derived by hand:
  // the eight cells around it). Letting go when the move towards the goal is free (Bug0): the right hand turns
  // East to (3, 1), where South is free again, and goes down to the goal in 8 moves; the left hand turns West to
  // (1, 1), where East is free again, steps back to (2, 1), meets the island again, and shuttles for good.
  const test::World w = test::world({"S....", ".....", "..#..", ".....", "....G"});
  const std::vector<Cell> staircase = {{0, 0}, {1, 0}, {1, 1}, {2, 1}};
  const std::vector<Cell> island = {{1, 1}, {1, 2}, {1, 3}, {2, 3}, {3, 3}, {3, 2}, {3, 1}, {2, 1}};
  for (const std::string& type : {"wall_follower_left", "wall_follower_right"}) {
    AgentConfig never = test::config(type);
    never.goal_seeking = kGoalSeekingOff;
    AgentConfig leaving = never;
    leaving.wall_leave = kWallLeaveGoalFree;
    const auto circling = test::runEpisode(*makeAgent(never), w, 1, 0.0, 60);
    EXPECT_FALSE(circling.passed) << type;
    ASSERT_GT(circling.path.size(), 40u) << type;
    for (std::size_t k = 0; k < staircase.size(); ++k) EXPECT_EQ(circling.path[k], staircase[k]) << type << k;
    std::set<std::pair<int, int>> first_lap;
    std::set<std::pair<int, int>> around;
    for (std::size_t k = 0; k < island.size(); ++k) {
      first_lap.insert({circling.path[4 + k].x, circling.path[4 + k].y});
      around.insert({island[k].x, island[k].y});
    }
    EXPECT_EQ(first_lap, around) << type;
    for (std::size_t k = 4 + island.size(); k < circling.path.size(); ++k) {
      EXPECT_EQ(circling.path[k], circling.path[k - island.size()]) << type << k;
    }
    const auto bug0 = test::runEpisode(*makeAgent(leaving), w, 1, 0.0, 60);
    if (type == "wall_follower_right") {
      const std::vector<Cell> expected = {{0, 0}, {1, 0}, {1, 1}, {2, 1}, {3, 1}, {3, 2}, {3, 3}, {4, 3}, {4, 4}};
      EXPECT_TRUE(bug0.passed);
      EXPECT_EQ(bug0.path, expected);
    } else {
      EXPECT_FALSE(bug0.passed);
      for (std::size_t k = 4; k < bug0.path.size(); ++k) EXPECT_EQ(bug0.path[k], k % 2 ? staircase[3] : staircase[2]);
    }
  }
}

TEST(AgentBehaviourTest, RandomGoalTiesDrawTheAxisWhereTheGoalIsAsFarAcrossAsDown) {
  // From the centre of an open 9x9 map to its corner, goal seeking off: the goal is as far across as down at every
  // other cell of the staircase. Across on a tie, the walk is East, South, East, ... (derived by hand); drawn, it
  // is a staircase all the same (8 moves, never more than one cell off the diagonal), its first move East for some
  // seeds and South for others, the same walk for the same seed.
  const test::World w = test::world({".........", ".........", ".........", ".........", "....S....", ".........",
                                     ".........", ".........", "........G"});
  for (const std::string& type : {"wall_follower_left", "wall_follower_right"}) {
    AgentConfig across = test::config(type);
    across.goal_seeking = kGoalSeekingOff;
    AgentConfig drawn = across;
    drawn.goal_ties = kGoalTiesRandom;
    std::vector<Cell> staircase;
    for (int k = 0; k <= 8; ++k) staircase.push_back(Cell{4 + (k + 1) / 2, 4 + k / 2});
    std::set<std::pair<int, int>> first_cells;
    for (std::uint64_t seed = 0; seed < 40; ++seed) {
      EXPECT_EQ(test::runEpisode(*makeAgent(across), w, seed, 0.0, 20).path, staircase) << type;
      const auto walk = test::runEpisode(*makeAgent(drawn), w, seed, 0.0, 20);
      EXPECT_EQ(walk.path, test::runEpisode(*makeAgent(drawn), w, seed, 0.0, 20).path) << type;
      ASSERT_TRUE(walk.passed) << type;
      EXPECT_EQ(walk.steps, 8) << type;
      for (const Cell cell : walk.path) EXPECT_LE(std::abs(cell.x - cell.y), 1) << type;
      first_cells.insert({walk.path[1].x, walk.path[1].y});
    }
    EXPECT_EQ(first_cells, (std::set<std::pair<int, int>>{{5, 4}, {4, 5}})) << type;
  }
}

TEST(AgentBehaviourTest, ExplorersBreakTiesTowardsTheGoalWhenAskedTo) {
  // From the centre of an open 11x11 map every first move reveals a new row or column of 5 cells: a four-way tie.
  // At random, the explorers take each of the four; towards the goal (bottom right), only East and South, which
  // bring it nearer, and both.
  const test::World w = test::world({"...........", "...........", "...........", "...........", "...........",
                                     ".....S.....", "...........", "...........", "...........", "...........",
                                     "..........G"});
  for (const std::string& type : {"explorer", "long_term_explorer"}) {
    for (const std::string& ties : {kExplorerTiesRandom, kExplorerTiesGoal}) {
      AgentConfig config = test::config(type);
      config.goal_seeking = kGoalSeekingOff;
      config.explorer_ties = ties;
      auto agent = makeAgent(config);
      std::set<std::pair<int, int>> first_cells;
      for (std::uint64_t seed = 0; seed < 40; ++seed) {
        const Cell first = test::runEpisode(*agent, w, seed, 0.0, 1).path.back();
        first_cells.insert({first.x, first.y});
      }
      const std::set<std::pair<int, int>> expected =
          ties == kExplorerTiesGoal ? std::set<std::pair<int, int>>{{6, 5}, {5, 6}}
                                    : std::set<std::pair<int, int>>{{6, 5}, {5, 6}, {4, 5}, {5, 4}};
      EXPECT_EQ(first_cells, expected) << type << " " << ties;
    }
  }
}

TEST(AgentBehaviourTest, AnIdleExplorerGoesWhereItStoodLeastOften) {
  // An open 5x2 map that a scan from x = 2 shows whole, goal seeking off: from then on nothing is new, so every move
  // is idle. Fed scans on row 0 at x = 1, 2, 1, 2 (two visits each), at (2, 0) the least-visited explorer goes
  // to one of the free neighbours never stood on, East or South, never West; the random one goes all three ways.
  const test::World w = test::world({"..S.G", "....."});
  const SensorModel sensor(SensorOptions{2, 0.0});
  for (const std::string& idle : {kExplorerIdleLeastVisited, kExplorerIdleRandom}) {
    AgentConfig config = test::config("explorer");
    config.goal_seeking = kGoalSeekingOff;
    config.explorer_idle = idle;
    auto agent = makeAgent(config);
    std::set<Action> chosen;
    for (std::uint64_t seed = 0; seed < 40; ++seed) {
      EpisodeInfo start;
      start.width = 5;
      start.height = 2;
      start.start = w.start;
      start.goal = w.goal;
      start.seed = seed;
      agent->reset(start);
      Action last = Action::Stay;
      int step = 0;
      for (const int x : {1, 2, 1, 2}) last = agent->act(Scan(sensor, w.grid, Cell{x, 0}, w.goal, false, step++, 0));
      chosen.insert(last);
    }
    if (idle == std::string(kExplorerIdleLeastVisited)) {
      EXPECT_EQ(chosen, (std::set<Action>{Action::East, Action::South}));
    } else {
      EXPECT_EQ(chosen, (std::set<Action>{Action::East, Action::South, Action::West}));
    }
  }
}

TEST(AgentBehaviourTest, AGoalSeekingRandomAgentWalksStraightToAGoalInView) {
  // On an empty 5x5 map from (2,2) the goal (4,4) is in the window at once: four moves, whatever the seed.
  AgentConfig random = test::config("random");
  random.goal_seeking = kGoalSeekingOn;
  auto agent = makeAgent(random);
  test::World w = test::world({".....", ".....", "..S..", ".....", "....G"});
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const auto out = test::runEpisode(*agent, w, seed);
    EXPECT_TRUE(out.passed);
    EXPECT_EQ(out.steps, 4) << seed;
  }
}

TEST(AgentBehaviourTest, EveryAgentRunsOnRandomProblemsWithEveryHandicapAndSensorRange) {
  // Robustness: every type, memory window, noise level and sensor range on random valid problems, odd sizes
  // included; actions must always be valid and the deterministic agents must repeat themselves.
  int episodes = 0;
  int passes = 0;
  for (const std::string& type : agentTypeNames()) {
    for (const int memory : {0, 1, 3, 5}) {
      for (const double noise : {0.0, 0.2}) {
        auto agent = makeAgent(test::config(type, memory, noise));
        Rng rng(deriveSeed(5, {static_cast<std::uint64_t>(memory), noise > 0 ? 1u : 0u}));
        for (int i = 0; i < 6; ++i) {
          const int width = 2 + static_cast<int>(rng.below(20));
          const int height = 2 + static_cast<int>(rng.below(20));
          const Problem problem = randomProblem(rng, Problem::empty(width, height, 8), 8);
          const test::World w{decodeGrid(problem), problem.start, problem.goal};
          const int range = 1 + i % 3;
          const auto out = test::runEpisode(*agent, w, rng.next(), noise, 120, type == "astar", range);
          const auto again = test::runEpisode(*agent, w, 77, noise, 120, type == "astar", range);
          const auto third = test::runEpisode(*agent, w, 77, noise, 120, type == "astar", range);
          EXPECT_EQ(again.path, third.path) << type;
          EXPECT_LE(out.steps, 120);
          ++episodes;
          passes += out.passed ? 1 : 0;
        }
      }
    }
  }
  std::printf("[ measured ] %d of %d robustness episodes passed\n", passes, episodes);
  EXPECT_EQ(episodes, 8 * 4 * 2 * 6);
}

}  // namespace
}  // namespace agents
}  // namespace ppp
