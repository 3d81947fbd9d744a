// A robot with a body: its footprint and configuration space on maps worked by hand.

#include "ppp_core/footprint.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ppp_core/episode.hpp"
#include "ppp_core/reachability.hpp"

namespace ppp {
namespace {

Grid gridOf(const std::vector<std::string>& rows) {
  Grid grid(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()));
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) grid.setObstacle(Cell{x, y}, rows[y][x] == '#');
  }
  return grid;
}

TEST(FootprintTest, DiscsCoverTheCellsTheyComeNearerThanTheirRadius) {
  // A neighbour's side is 0.5 from the centre, a diagonal neighbour's corner 0.71, the cell two away 1.5, the
  // knight's-move cell (2, 1) 1.58 and the cell (2, 2) 2.12.
  EXPECT_EQ(footprintOffsets(0.5).size(), 1u);   // touches its neighbours' sides: a point robot
  EXPECT_TRUE(isPointRobot(0.5));
  EXPECT_FALSE(isPointRobot(0.6));
  EXPECT_EQ(footprintOffsets(0.6).size(), 5u);   // the cell and its four neighbours
  EXPECT_EQ(footprintOffsets(1).size(), 9u);     // the 3x3 block
  EXPECT_EQ(footprintOffsets(1.5).size(), 9u);   // (2, 0) only touched
  EXPECT_EQ(footprintOffsets(1.6).size(), 21u);  // 5x5 but its corners
}

TEST(FootprintTest, ADiscOfRadiusOnePassesAThreeCellCorridorAndBumpsIntoATwoCellOne) {
  // Rows 1-3 are open on the left, only rows 1-2 from x = 4 on.
  const Grid grid = gridOf({"#########", ".........", ".........", "....#####", "#########"});
  const Grid space = configurationSpace(grid, 1);
  for (int x = 1; x <= 2; ++x) EXPECT_TRUE(space.isFree(Cell{x, 2})) << x;
  EXPECT_FALSE(space.isFree(Cell{0, 2}));  // the disc would leave the map
  EXPECT_FALSE(space.isFree(Cell{3, 2}));  // it would cover the wall at (4, 3)
  EXPECT_FALSE(space.isFree(Cell{2, 1}));  // it would cover the top wall
  Problem problem = Problem::empty(9, 5, 1);
  problem.start = Cell{1, 2};
  problem.goal = Cell{7, 1};
  const SensorModel sensor(SensorOptions{2, 0.0});
  Episode episode(problem, grid, sensor, 1, 10, Connectivity::Four, true, nullptr, &space);
  episode.apply(Action::East);
  EXPECT_FALSE(episode.scan().bumped());
  episode.apply(Action::East);  // into the two-cell corridor: the disc hits the wall at (4, 3)
  EXPECT_TRUE(episode.scan().bumped());
  EXPECT_EQ(episode.outcome().path.back(), (Cell{2, 2}));
  // The point robot walks on.
  Episode point(problem, grid, sensor, 1, 10, Connectivity::Four, true);
  point.apply(Action::East);
  point.apply(Action::East);
  EXPECT_FALSE(point.scan().bumped());
  EXPECT_FALSE(isReachable(space, problem.start, problem.goal));
  EXPECT_TRUE(isReachable(grid, problem.start, problem.goal));
}

TEST(FootprintTest, APointRobotMovesOnTheGridItself) {
  const Grid grid = gridOf({"...", ".#.", "..."});
  Grid space;
  EXPECT_EQ(&motionGrid(grid, 0, &space), &grid);
  EXPECT_EQ(&motionGrid(grid, 1, &space), &space);
  EXPECT_EQ(space.obstacleCount(), 9);  // a 3x3 map has no cell the 3x3 disc fits in off its obstacle
}

}  // namespace
}  // namespace ppp
