#include "ppp_core/octile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/movingai_map.hpp"
#include "ppp_core/movingai_scen.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace {

const double kRoot2 = std::sqrt(2.0);

// Rows of '.' (free) and '#' (obstacle), y down.
Grid gridOf(const std::vector<std::string>& rows) {
  Grid grid(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()));
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) grid.setObstacle(Cell{x, y}, rows[y][x] == '#');
  }
  return grid;
}

// Every pair's cost by relaxing every allowed move until nothing changes (Bellman-Ford): independent of A*.
std::vector<double> relaxedCosts(const Grid& grid, Cell start) {
  std::vector<double> cost(static_cast<std::size_t>(grid.size()), INFINITY);
  cost[grid.index(start)] = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (int i = 0; i < grid.size(); ++i) {
      const Cell c = grid.cellAt(i);
      if (!grid.isFree(c) || std::isinf(cost[i])) continue;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          if ((dx == 0 && dy == 0) || !octileMoveAllowed(grid, c, dx, dy)) continue;
          const int j = grid.index(Cell{c.x + dx, c.y + dy});
          const double through = cost[i] + (dx != 0 && dy != 0 ? kRoot2 : 1.0);
          if (through < cost[j] - 1e-12) cost[j] = through, changed = true;
        }
      }
    }
  }
  return cost;
}

TEST(OctileTest, DistanceOnAnEmptyMapIsStraightPlusDiagonalSteps) {
  EXPECT_DOUBLE_EQ(octileDistance(Cell{0, 0}, Cell{3, 1}), 2 + kRoot2);
  EXPECT_DOUBLE_EQ(octileDistance(Cell{4, 4}, Cell{0, 0}), 4 * kRoot2);
  EXPECT_DOUBLE_EQ(octileDistance(Cell{2, 5}, Cell{2, 1}), 4);
  EXPECT_DOUBLE_EQ(octileDistance(Cell{2, 5}, Cell{2, 5}), 0);
}

TEST(OctileTest, OpenDiagonalCostsRootTwo) {
  const OctileRoute route = shortestOctileRoute(gridOf({"....", "....", "....", "...."}), Cell{0, 0}, Cell{3, 3});
  EXPECT_NEAR(route.length, 3 * kRoot2, 1e-12);
  EXPECT_EQ(route.cells, (std::vector<Cell>{{0, 0}, {1, 1}, {2, 2}, {3, 3}}));
}

TEST(OctileTest, NoCornerIsCut) {
  // (0,0) -> (2,0) past the obstacle at (1,0): the diagonals (0,0)-(1,1) and (1,1)-(2,0) each pass it, so the
  // route goes down, across and up: 4, not 2 sqrt(2) = 2.83.
  const Grid grid = gridOf({".#.", "..."});
  EXPECT_FALSE(octileMoveAllowed(grid, Cell{0, 0}, 1, 1));
  EXPECT_FALSE(octileMoveAllowed(grid, Cell{1, 1}, 1, -1));
  EXPECT_TRUE(octileMoveAllowed(grid, Cell{0, 1}, 1, 0));
  const OctileRoute route = shortestOctileRoute(grid, Cell{0, 0}, Cell{2, 0});
  EXPECT_DOUBLE_EQ(route.length, 4);
  EXPECT_EQ(route.cells, (std::vector<Cell>{{0, 0}, {0, 1}, {1, 1}, {2, 1}, {2, 0}}));
  // One free orthogonal neighbour is not enough either: (0,1) -> (1,0) passes the obstacle at (1,1).
  const Grid half = gridOf({"..", ".#"});
  EXPECT_FALSE(octileMoveAllowed(half, Cell{0, 1}, 1, -1));
  EXPECT_DOUBLE_EQ(shortestOctileRoute(half, Cell{0, 1}, Cell{1, 0}).length, 2);
}

TEST(OctileTest, UnreachableGoalAndBlockedEnds) {
  const Grid wall = gridOf({".#.", ".#.", ".#."});
  const OctileRoute route = shortestOctileRoute(wall, Cell{0, 0}, Cell{2, 2});
  EXPECT_EQ(route.length, -1);
  EXPECT_TRUE(route.cells.empty());
  EXPECT_EQ(shortestOctileRoute(wall, Cell{1, 1}, Cell{0, 0}).length, -1);  // start on an obstacle
  const OctileRoute stay = shortestOctileRoute(wall, Cell{2, 1}, Cell{2, 1});
  EXPECT_EQ(stay.length, 0);
  EXPECT_EQ(stay.cells, (std::vector<Cell>{Cell{2, 1}}));
}

TEST(OctileTest, CellsOffTheGridAreRefused) {
  const Grid grid(3, 3);
  EXPECT_THROW(shortestOctileRoute(grid, Cell{-1, 0}, Cell{2, 2}), InvalidArgument);
  EXPECT_THROW(shortestOctileRoute(grid, Cell{0, 0}, Cell{3, 2}), InvalidArgument);
}

TEST(OctileTest, MatchesRelaxationOnRandomMaps) {
  Rng rng(7);
  for (int map = 0; map < 40; ++map) {
    Grid grid(9, 7);
    for (int i = 0; i < grid.size(); ++i) grid.setObstacle(grid.cellAt(i), rng.below(100) < 30);
    const Cell start{static_cast<int>(rng.below(9)), static_cast<int>(rng.below(7))};
    grid.setObstacle(start, false);
    const std::vector<double> expected = relaxedCosts(grid, start);
    for (int i = 0; i < grid.size(); ++i) {
      const Cell goal = grid.cellAt(i);
      const OctileRoute route = shortestOctileRoute(grid, start, goal);
      if (std::isinf(expected[i])) {
        EXPECT_EQ(route.length, -1) << "map " << map << " goal " << i;
        continue;
      }
      ASSERT_NEAR(route.length, expected[i], 1e-9) << "map " << map << " goal " << i;
      // The route itself is made of allowed moves whose costs add up to its length.
      double walked = 0;
      for (std::size_t k = 1; k < route.cells.size(); ++k) {
        const int dx = route.cells[k].x - route.cells[k - 1].x;
        const int dy = route.cells[k].y - route.cells[k - 1].y;
        ASSERT_TRUE(octileMoveAllowed(grid, route.cells[k - 1], dx, dy));
        walked += dx != 0 && dy != 0 ? kRoot2 : 1.0;
      }
      EXPECT_NEAR(walked, route.length, 1e-9);
      EXPECT_EQ(route.cells.front(), start);
      EXPECT_EQ(route.cells.back(), goal);
    }
  }
}

TEST(OctileTest, ReproducesThePublishedLengthsOfADragonAgeMap) {
  // The benchmark's own arena map and its 130 scenarios (test/data/movingai/README.md).
  const std::string dir = std::string(PPP_TEST_DATA_DIR) + "/movingai/";
  const Grid map = decodeGrid(readMovingAiMap(dir + "arena.map"));
  const std::vector<MovingAiScenario> scenarios = readMovingAiScenarios(dir + "arena.map.scen");
  ASSERT_EQ(scenarios.size(), 130u);
  for (const MovingAiScenario& s : scenarios) {
    checkScenarioOnMap(s, map, dir + "arena.map.scen");
    EXPECT_NEAR(shortestOctileRoute(map, s.start, s.goal).length, s.optimal_length, 1e-6)
        << "line " << s.line;
  }
}

}  // namespace
}  // namespace ppp
