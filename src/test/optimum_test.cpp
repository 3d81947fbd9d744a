// The yardstick of a run: optima, relative budgets, regret and soft failures on maps worked by hand.

#include "ppp_core/optimum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ppp_core/reachability.hpp"

namespace ppp {
namespace {

const double kRoot2 = std::sqrt(2.0);

/// A problem on rows of '.' (free) and '#' (obstacle), y down, from `start` to `goal`, and its grid.
struct Drawn {
  Problem problem;
  Grid grid;
};

Drawn drawn(const std::vector<std::string>& rows, Cell start, Cell goal) {
  Drawn d;
  d.problem = Problem::empty(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()), 1);
  d.problem.start = start;
  d.problem.goal = goal;
  d.grid = Grid(d.problem.width, d.problem.height);
  for (int y = 0; y < d.grid.height(); ++y) {
    for (int x = 0; x < d.grid.width(); ++x) d.grid.setObstacle(Cell{x, y}, rows[y][x] == '#');
  }
  return d;
}

TEST(OptimumTest, FewestMovesAndLengthFollowTheMoveModel) {
  // An empty 5x5 map corner to corner: 8 straight moves 4-connected; 4 diagonals 8-connected, 4 sqrt(2) long.
  const Drawn open = drawn({".....", ".....", ".....", ".....", "....."}, {0, 0}, {4, 4});
  EXPECT_EQ(optimumOf(open.problem, open.grid, Connectivity::Four).moves, 8);
  EXPECT_DOUBLE_EQ(optimumOf(open.problem, open.grid, Connectivity::Four).length, 8);
  EXPECT_EQ(optimumOf(open.problem, open.grid, Connectivity::Eight).moves, 4);
  EXPECT_NEAR(optimumOf(open.problem, open.grid, Connectivity::Eight).length, 4 * kRoot2, 1e-12);
  // A wall at x = 2 open only in the bottom row, from (0,0) to (4,0). 4-connected: 6 moves to the gap (2,4) and 6
  // back up: 12. 8-connected: the gap is entered and left only straight ((2,3) is wall, so no diagonal passes it),
  // so each side needs 4 moves down and the step across: 5 moves, one of them diagonal (4 + sqrt(2) long): 10.
  const Drawn wall = drawn({"..#..", "..#..", "..#..", "..#..", "....."}, {0, 0}, {4, 0});
  EXPECT_EQ(optimumOf(wall.problem, wall.grid, Connectivity::Four).moves, 12);
  EXPECT_EQ(optimumOf(wall.problem, wall.grid, Connectivity::Eight).moves, 10);
  EXPECT_NEAR(optimumOf(wall.problem, wall.grid, Connectivity::Eight).length, 8 + 2 * kRoot2, 1e-12);
  // A closed wall: unreachable either way.
  const Drawn closed = drawn({"..#..", "..#..", "..#.."}, {0, 0}, {4, 0});
  EXPECT_EQ(optimumOf(closed.problem, closed.grid, Connectivity::Four).moves, -1);
  EXPECT_EQ(optimumOf(closed.problem, closed.grid, Connectivity::Eight).length, -1);
}

TEST(OptimumTest, FewestMovesFourConnectedAreTheBreadthFirstDistances) {
  const Drawn wall = drawn({"..#..", "..#..", "..#..", "..#..", "....."}, {0, 0}, {4, 0});
  const std::vector<int> distances = stepDistances(wall.grid, {0, 0});
  for (int i = 0; i < wall.grid.size(); ++i) {
    EXPECT_EQ(fewestMoves(wall.grid, {0, 0}, wall.grid.cellAt(i), Connectivity::Four), distances[i]) << i;
  }
}

TEST(OptimumTest, RelativeBudgetsScaleWithTheOptimum) {
  EpisodeOptions absolute;
  EXPECT_EQ(episodeBudget(absolute, 38), 300);  // the absolute budget whatever the optimum
  absolute.budget_min = 400;
  EXPECT_EQ(episodeBudget(absolute, 38), 400);  // a floor for it too
  EpisodeOptions relative;
  relative.budget_factor = 2;
  EXPECT_EQ(episodeBudget(relative, 38), 76);
  relative.budget_factor = 1.1;
  EXPECT_EQ(episodeBudget(relative, 40), 44);   // 1.1 x 40 is 44.000000000000007 in doubles: still 44
  EXPECT_EQ(episodeBudget(relative, 41), 46);   // ceil(45.1)
  relative.budget_min = 50;
  EXPECT_EQ(episodeBudget(relative, 40), 50);
  relative.budget_factor = 1000;
  EXPECT_EQ(episodeBudget(relative, 999999), kMaxEpisodeBudget);
  // From a PPP: the 8-connected optimum of the open 5x5 map takes 4 moves, the 4-connected one 8.
  const Drawn open = drawn({".....", ".....", ".....", ".....", "....."}, {0, 0}, {4, 4});
  EpisodeOptions twice;
  twice.budget_factor = 2;
  EXPECT_EQ(episodeBudget(twice, open.problem, open.grid), 16);
  twice.connectivity = Connectivity::Eight;
  EXPECT_EQ(episodeBudget(twice, open.problem, open.grid), 8);
}

TEST(OptimumTest, RegretCountsAFailedRunAsItsWholeBudget) {
  EXPECT_DOUBLE_EQ(runRegret(true, 38, 300, 38), 0);
  EXPECT_DOUBLE_EQ(runRegret(true, 57, 300, 38), 0.5);
  EXPECT_DOUBLE_EQ(runRegret(false, 120, 300, 38), 262.0 / 38);  // ended early (a timeout): the whole budget
  EXPECT_DOUBLE_EQ(runRegret(false, 76, 76, 38), 1);
}

TEST(OptimumTest, ASoftFailureIsAPassedRunLongerThanTheRatioAllows) {
  EXPECT_FALSE(isSoftFailure(true, 100, 38, 0));    // no ratio: never
  EXPECT_FALSE(isSoftFailure(true, 57, 38, 1.5));   // exactly 1.5 x: not longer
  EXPECT_TRUE(isSoftFailure(true, 58, 38, 1.5));
  EXPECT_FALSE(isSoftFailure(false, 300, 38, 1.5));  // a failed run is a hard failure, not a soft one
}

}  // namespace
}  // namespace ppp
