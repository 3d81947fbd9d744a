#include "ppp_core/failure_signature.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "grid_picture.hpp"
#include "ppp_core/episode_reason.hpp"
#include "ppp_core/reachability.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace {

/// A grid from rows of '.' (free) and '#' (obstacle).
Grid gridOf(const std::vector<std::string>& rows) { return test::picture(rows).grid; }

// The map of the hand-worked cases: start (0,0), goal (5,3).
//   S..#..
//   ...#..
//   .#....
//   .....G
const Grid kMap = gridOf({"...#..", "...#..", ".#....", "......"});
const Cell kStart{0, 0};
const Cell kGoal{5, 3};

Diagnosis kind(const char* k, int step = -1, int period = 0) {
  Diagnosis d;
  d.kind = k;
  d.step = step;
  d.period = period;
  return d;
}

TEST(FailureSignatureTest, ACleanPassHasNone) {
  const SignatureMap map(kMap, kMap, kStart, kGoal);
  EXPECT_EQ(failureSignature(map, Diagnosis{}, reason::kGoalReached, {kStart, Cell{1, 0}}), "");
}

TEST(FailureSignatureTest, ANoPathBesideTheGoalNamesWhereItWasToldAndTheGoalsShape) {
  // Told "no path" on (4,3): 1 move from the goal, 7 from the start (4 + 3 on a free L); its south side is the
  // map's edge, no obstacle touches it. The goal (5,3) is in the corner: two sides and three diagonals off the map.
  const SignatureMap map(kMap, kMap, kStart, kGoal);
  const std::vector<Cell> cells = {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {1, 3}, {2, 3}, {3, 3}, {4, 3}};
  EXPECT_EQ(failureSignature(map, kind(diagnosis::kMissedRoute), reason::kNoPath, cells),
            "missed_route/g1/s4-7/t1/w0e1/G0e2d3");
}

TEST(FailureSignatureTest, AStuckRobotIsPlacedOnItsCellBesideTheWall) {
  // Stuck on (2,1) from step 3: the wall (3,1) to its east; 5 moves to the goal round the wall's foot, 3 from the
  // start.
  const SignatureMap map(kMap, kMap, kStart, kGoal);
  std::vector<Cell> cells = {{0, 0}, {1, 0}, {2, 0}, {2, 1}};
  cells.insert(cells.end(), 12, Cell{2, 1});
  const Diagnosis d = diagnoseTrajectory(cells);
  ASSERT_STREQ(d.kind, diagnosis::kStuck);
  EXPECT_EQ(failureSignature(map, d, reason::kBudgetExhausted, cells), "stuck/g4-7/s2-3/t0/w1e0");
}

TEST(FailureSignatureTest, ALoopIsPlacedOnItsCellNearestTheGoalWithItsPeriodsClass) {
  // Shuttling between (0,1) and (0,2): of the two, (0,2) is nearer the goal (6 moves, against 7); it has the
  // obstacle (1,2) to its east and the edge to its west.
  const SignatureMap map(kMap, kMap, kStart, kGoal);
  std::vector<Cell> cells = {{0, 0}};
  for (int i = 0; i < 10; ++i) {
    cells.push_back(Cell{0, 1});
    cells.push_back(Cell{0, 2});
  }
  const Diagnosis d = diagnoseTrajectory(cells);
  ASSERT_STREQ(d.kind, diagnosis::kLoop);
  ASSERT_EQ(d.period, 2);
  EXPECT_EQ(failureSignature(map, d, reason::kBudgetExhausted, cells), "loop2/g4-7/s2-3/t0/w1e1");
  // The same loop with a longer cycle falls in another class.
  EXPECT_EQ(failureSignature(map, kind(diagnosis::kLoop, 1, 6), reason::kBudgetExhausted, cells),
            "loop5-8/g4-7/s2-3/t0/w1e1");
}

TEST(FailureSignatureTest, AWanderingRunIsPlacedOnItsNearestApproach) {
  // Down the west column and one step east, then back: (1,3) is 4 moves from the goal and 4 from the start,
  // with the obstacle (1,2) to its north and the edge to its south.
  const SignatureMap map(kMap, kMap, kStart, kGoal);
  const std::vector<Cell> cells = {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {1, 3}, {0, 3}, {0, 2}};
  EXPECT_EQ(failureSignature(map, kind(diagnosis::kWandering, 4), reason::kBudgetExhausted, cells),
            "wandering/g4-7/s4-7/t1/w1e1");
}

TEST(FailureSignatureTest, ADetourIsPlacedOnItsFarthestExcursion) {
  // On an empty 5x3 map from (0,0) to (4,0) by the bottom row: every cell of that row is 8 moves off a shortest
  // route's 4 (start to cell to goal); the first of them, (0,2), is the site: 6 moves from the goal, 2 from the
  // start, in the south-west corner.
  const Grid empty = gridOf({".....", ".....", "....."});
  const SignatureMap map(empty, empty, Cell{0, 0}, Cell{4, 0});
  const std::vector<Cell> cells = {{0, 0}, {0, 1}, {0, 2}, {1, 2}, {2, 2}, {3, 2}, {4, 2}, {4, 1}, {4, 0}};
  EXPECT_EQ(failureSignature(map, kind(diagnosis::kDetour), reason::kGoalReached, cells), "detour/g4-7/s2-3/t1/w0e2");
}

TEST(FailureSignatureTest, AReportedEndingIsNamedByItsReason) {
  const SignatureMap map(kMap, kMap, kStart, kGoal);
  // Ended before any cell was recorded: on the start, in the corner beside nothing, 8 moves from the goal.
  EXPECT_EQ(failureSignature(map, kind(diagnosis::kReported), reason::kAgentLost, {}), "agent_lost/g8-15/s0/t0/w0e2");
  EXPECT_EQ(failureSignature(map, kind(diagnosis::kReported), reason::kCollision, {{0, 0}, {1, 0}, {2, 0}}),
            "collision/g4-7/s2-3/t0/w1e1");
}

TEST(FailureSignatureTest, DistancesAreReadOnTheGridTheRobotMovesOn) {
  // A motion grid (as a body's configuration space would be) with the column x = 4 blocked: from (5,0) the goal is
  // 3 moves down, but the start no longer reaches (5,0) at all. The shapes are the PPP's.
  const Grid motion = gridOf({"...##.", "...##.", ".#..#.", "....#."});
  const SignatureMap map(kMap, motion, kStart, kGoal);
  EXPECT_EQ(failureSignature(map, kind(diagnosis::kReported), reason::kPlannerTimeout, {{5, 0}}),
            "planner_timeout/g2-3/sx/t0/w0e2/G0e2d3");
}

/// The cell `c` of a w x h grid under symmetry `s` of the square's eight (bit 0: mirror x, bit 1: mirror y, bit 2:
/// transpose; a transposed grid is h x w).
Cell transformed(Cell c, int w, int h, int s) {
  if ((s & 1) != 0) c.x = w - 1 - c.x;
  if ((s & 2) != 0) c.y = h - 1 - c.y;
  if ((s & 4) != 0) std::swap(c.x, c.y);
  return c;
}

TEST(FailureSignatureTest, ARunMovedMirroredOrRotatedWithItsMapKeepsItsSignature) {
  // Random maps and random walks: every signature counts sides and moves, which no symmetry of the square changes.
  Rng rng(7);
  int compared = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int w = 4 + static_cast<int>(rng.uniformInt(0, 5)), h = 4 + static_cast<int>(rng.uniformInt(0, 5));
    Grid grid(w, h);
    for (int i = 0; i < grid.size(); ++i) grid.setObstacle(grid.cellAt(i), rng.uniformInt(0, 3) == 0);
    const Cell start{0, 0}, goal{w - 1, h - 1};
    grid.setObstacle(start, false);
    grid.setObstacle(goal, false);
    std::vector<Cell> cells = {start};
    for (int t = 0; t < 30; ++t) {
      const Cell c = cells.back();
      const Cell steps[] = {{c.x + 1, c.y}, {c.x - 1, c.y}, {c.x, c.y + 1}, {c.x, c.y - 1}};
      const Cell next = steps[rng.uniformInt(0, 3)];
      cells.push_back(grid.isFree(next) ? next : c);
    }
    const Diagnosis d = diagnoseRun(false, false, reason::kBudgetExhausted, cells);
    const std::string expected = failureSignature(SignatureMap(grid, grid, start, goal), d, reason::kBudgetExhausted, cells);
    ASSERT_TRUE(isWellFormedSignature(expected)) << expected;
    for (int s = 1; s < 8; ++s) {
      const bool swap = (s & 4) != 0;
      Grid moved(swap ? h : w, swap ? w : h);
      for (int i = 0; i < grid.size(); ++i) moved.setObstacle(transformed(grid.cellAt(i), w, h, s), grid.cells()[i] != 0);
      std::vector<Cell> moved_cells;
      for (const Cell c : cells) moved_cells.push_back(transformed(c, w, h, s));
      const SignatureMap map(moved, moved, transformed(start, w, h, s), transformed(goal, w, h, s));
      EXPECT_EQ(failureSignature(map, d, reason::kBudgetExhausted, moved_cells), expected) << "trial " << trial;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 1400);
}

TEST(FailureSignatureTest, DifferentFailuresOnOneMapGetDifferentSignatures) {
  const SignatureMap map(kMap, kMap, kStart, kGoal);
  const std::vector<Cell> to_wall = {{0, 0}, {1, 0}, {2, 0}, {2, 1}};
  const std::vector<Cell> to_goal = {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {1, 3}, {2, 3}, {3, 3}, {4, 3}};
  const std::string a = failureSignature(map, kind(diagnosis::kMissedRoute), reason::kNoPath, to_wall);
  const std::string b = failureSignature(map, kind(diagnosis::kMissedRoute), reason::kNoPath, to_goal);
  const std::string c = failureSignature(map, kind(diagnosis::kReported), reason::kPlannerTimeout, to_goal);
  EXPECT_NE(a, b);
  EXPECT_NE(b, c);
}

TEST(FailureSignatureTest, OnlyWhatItWritesIsWellFormed) {
  std::string why;
  EXPECT_TRUE(isWellFormedSignature(""));
  EXPECT_TRUE(isWellFormedSignature("missed_route/g1/s4-7/t1/w0e1/G0e2d3"));
  EXPECT_TRUE(isWellFormedSignature("loop2/g64+/sx/t4/w4e0"));
  EXPECT_FALSE(isWellFormedSignature("loop2/g4-7/s2-3", &why));
  EXPECT_NE(why.find("expected HOW/gG/sS/tT/wOeE"), std::string::npos) << why;
  EXPECT_FALSE(isWellFormedSignature("loop2/g5/s2-3/t0/w1e1", &why));
  EXPECT_NE(why.find("goal distance 'g5'"), std::string::npos) << why;
  EXPECT_FALSE(isWellFormedSignature("loop2/g4-7/s2-3/t0/w5e1", &why));
  EXPECT_FALSE(isWellFormedSignature("loop2/g4-7/s2-3/t0/w1e3"));
  EXPECT_FALSE(isWellFormedSignature("missed_route/g1/s4-7/t1/w0e1", &why));
  EXPECT_NE(why.find("within 3 moves"), std::string::npos) << why;
  EXPECT_FALSE(isWellFormedSignature("loop2/g16-31/s1/t0/w0e0/G0e2d3"));
  EXPECT_FALSE(isWellFormedSignature("missed_route/g1/s4-7/t1/w0e1/G0e2d5"));
  EXPECT_FALSE(isWellFormedSignature("no path/g1/s4-7/t1/w0e1/G0e2d3"));
  EXPECT_FALSE(isWellFormedSignature("/g1/s4-7/t1/w0e1/G0e2d3"));
  EXPECT_FALSE(isWellFormedSignature("loop2/g4-7/s2-3/t5/w1e1"));
}

}  // namespace
}  // namespace ppp
