#include "ppp_agents/navigation.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace ppp {
namespace agents {
namespace {

/// Memory filled from a drawing ('.' free, '#' obstacle, '?' unknown) through one received full-map scan.
AgentMemory drawnMemory(const std::vector<std::string>& rows) {
  const int height = static_cast<int>(rows.size());
  const int width = static_cast<int>(rows[0].size());
  const int range = 7;
  std::vector<std::int8_t> cells;
  for (int dy = -range; dy <= range; ++dy) {
    for (int dx = -range; dx <= range; ++dx) {
      const int x = dx + range;
      const int y = dy + range;
      if (x >= width || y >= height) {
        cells.push_back(kScanOutOfBounds);
        continue;
      }
      const char c = rows[y][x];
      cells.push_back(c == '.' ? kScanFree : c == '#' ? kScanObstacle : kScanUnknown);
    }
  }
  AgentMemory memory;
  memory.reset(width, height, 0);
  memory.update(Scan(range, cells, Cell{range, range}, Cell{0, 0}, false, 0));
  return memory;
}

TEST(NavigationTest, GoalSeenOnlyWhenInTheWindowAndReportedFree) {
  std::vector<std::int8_t> cells(25, kScanFree);
  EXPECT_TRUE(goalSeen(Scan(2, cells, Cell{5, 5}, Cell{7, 3}, false, 0), 0));
  EXPECT_FALSE(goalSeen(Scan(2, cells, Cell{5, 5}, Cell{8, 5}, false, 0), 0));
  EXPECT_TRUE(goalNearby(Scan(2, cells, Cell{5, 5}, Cell{3, 7}, false, 0), 0));
  EXPECT_FALSE(goalNearby(Scan(2, cells, Cell{5, 5}, Cell{5, 8}, false, 0), 0));
  cells[0] = kScanUnknown;  // offset (-2, -2): hidden
  EXPECT_FALSE(goalSeen(Scan(2, cells, Cell{5, 5}, Cell{3, 3}, false, 0), 0));
  cells[0] = kScanObstacle;  // misreported by noise
  EXPECT_FALSE(goalSeen(Scan(2, cells, Cell{5, 5}, Cell{3, 3}, false, 0), 0));
}

TEST(NavigationTest, AGoalRangeNoticesTheGoalWithinItsCellsWhateverLiesBetween) {
  std::vector<std::int8_t> cells(25, kScanObstacle);  // a window of walls: nothing is seen free
  // Goal range 3: noticed at Chebyshev distance 3 (outside the 5x5 window) and behind a reported wall, not at 4.
  EXPECT_TRUE(goalSeen(Scan(2, cells, Cell{5, 5}, Cell{8, 2}, false, 0), 3));
  EXPECT_TRUE(goalSeen(Scan(2, cells, Cell{5, 5}, Cell{4, 6}, false, 0), 3));
  EXPECT_FALSE(goalSeen(Scan(2, cells, Cell{5, 5}, Cell{9, 5}, false, 0), 3));
  EXPECT_TRUE(goalNearby(Scan(2, cells, Cell{5, 5}, Cell{2, 8}, false, 0), 3));
  EXPECT_FALSE(goalNearby(Scan(2, cells, Cell{5, 5}, Cell{5, 9}, false, 0), 3));
  // Goal range 1 is shorter than the window: the goal two cells away is noticed when seen free, and only then;
  // one cell away it is noticed behind a wall.
  std::vector<std::int8_t> open(25, kScanFree);
  EXPECT_TRUE(goalSeen(Scan(2, open, Cell{5, 5}, Cell{7, 5}, false, 0), 1));
  EXPECT_FALSE(goalSeen(Scan(2, cells, Cell{5, 5}, Cell{7, 5}, false, 0), 1));
  EXPECT_TRUE(goalSeen(Scan(2, cells, Cell{5, 5}, Cell{6, 4}, false, 0), 1));
  EXPECT_TRUE(goalNearby(Scan(2, cells, Cell{5, 5}, Cell{7, 3}, false, 0), 1));
}

TEST(NavigationTest, TowardsGoalTakesAShortestPathTreatingUnknownAsPassable) {
  // (0,0) to (2,0): the wall at x = 1 is known in rows 0-1 and row 2 is unknown, so the optimistic path
  // goes round the end of the wall through the unknown row: south first.
  const AgentMemory memory = drawnMemory({
      ".#..",
      ".#..",
      "????",
  });
  Navigator navigator;
  navigator.reset(4, 3);
  Action action = Action::Stay;
  ASSERT_TRUE(navigator.towardsGoal(memory, Cell{0, 0}, Cell{2, 0}, &action));
  EXPECT_EQ(action, Action::South);
  // Walled off by known obstacles: no path.
  const AgentMemory closed = drawnMemory({
      ".#..",
      ".#..",
      ".#..",
  });
  EXPECT_FALSE(navigator.towardsGoal(closed, Cell{0, 0}, Cell{2, 0}, &action));
  // The goal itself counts as passable even when (mis)remembered as an obstacle.
  const AgentMemory goal_misread = drawnMemory({
      "..#",
      "...",
  });
  navigator.reset(3, 2);
  ASSERT_TRUE(navigator.towardsGoal(goal_misread, Cell{1, 0}, Cell{2, 0}, &action));
  EXPECT_EQ(action, Action::East);
}

TEST(NavigationTest, TowardsSeenGoalHeadsForTheGoalFromTheFirstScanShowingIt) {
  const AgentMemory memory = drawnMemory({
      "....",
      "....",
      "....",
  });
  Navigator navigator;
  navigator.reset(4, 3);
  const Cell goal{3, 0};
  std::vector<std::int8_t> cells(25, kScanFree);
  bool goal_seen = false;
  Action action = Action::Stay;
  // From (0,2) the goal is outside the range-2 window: not seen, no move.
  EXPECT_FALSE(navigator.towardsSeenGoal(Scan(2, cells, Cell{0, 2}, goal, false, 0), memory, 0, &goal_seen, &action));
  EXPECT_FALSE(goal_seen);
  // From (1,1) it is in the window and reported free: seen; N, E, E is the first of the 3-move paths found.
  ASSERT_TRUE(navigator.towardsSeenGoal(Scan(2, cells, Cell{1, 1}, goal, false, 1), memory, 0, &goal_seen, &action));
  EXPECT_TRUE(goal_seen);
  EXPECT_EQ(action, Action::North);
  // Hidden in a later scan (offset (2, -1)): still heading for it.
  cells[1 * 5 + 4] = kScanUnknown;
  action = Action::Stay;
  ASSERT_TRUE(navigator.towardsSeenGoal(Scan(2, cells, Cell{1, 1}, goal, false, 2), memory, 0, &goal_seen, &action));
  EXPECT_EQ(action, Action::North);
}

TEST(NavigationTest, SearchLeastWeighsTheWalkAndTheCostBeyond) {
  // From (2,0) on an open 5x3 map, targets (0,0) at 2 steps with cost 5 and (4,2) at 4 steps with cost 0: the
  // second scores 4 against 7. With costs 0 and 3 the first scores 2 against 7; with 2 and 0 they tie at 4.
  const AgentMemory memory = drawnMemory({
      ".....",
      ".....",
      ".....",
  });
  Navigator navigator;
  navigator.reset(5, 3);
  const auto free = [&](Cell c) { return memory.isFree(c); };
  const auto costs = [](int a, int b) {
    return [a, b](Cell c) { return c == Cell{0, 0} ? a : c == Cell{4, 2} ? b : -1; };
  };
  EXPECT_EQ(navigator.searchLeast(Cell{2, 0}, free, costs(5, 0)), 2 * 5 + 4);
  std::vector<Cell> path;
  navigator.path(2 * 5 + 4, &path);
  EXPECT_EQ(path.size(), 4u);
  EXPECT_EQ(path.back(), (Cell{4, 2}));
  EXPECT_EQ(navigator.searchLeast(Cell{2, 0}, free, costs(0, 3)), 0);
  EXPECT_EQ(navigator.searchLeast(Cell{2, 0}, free, costs(2, 0)), 0);  // 4 against 4: the nearer
  EXPECT_EQ(navigator.firstAction(0), Action::West);
  EXPECT_EQ(navigator.searchLeast(Cell{2, 0}, free, costs(-1, -1)), -1);
}

TEST(NavigationTest, SearchFindsTheNearestFrontierAndItsPath) {
  const AgentMemory memory = drawnMemory({
      ".....#",
      ".###.#",
      ".#...#",
      ".#.?.#",
  });
  Navigator navigator;
  navigator.reset(6, 4);
  const auto frontier = [&](Cell c) {
    if (!memory.isFree(c)) return false;
    for (Action move : kMoves) {
      if (memory.isUnknown(target(c, move))) return true;
    }
    return false;
  };
  // The only unknown cell is (3,3); its free neighbours (3,2), (4,3) and (2,3) are the frontier. From (0,3)
  // the way is up column 0, along row 0 and down column 4 to (4,2) (9 moves); (4,3) and (3,2) are both 10
  // moves away, and (4,2) expands S before W, so (4,3) is found.
  const int found = navigator.search(
      Cell{0, 3}, [&](Cell c) { return memory.isFree(c); }, frontier);
  ASSERT_GE(found, 0);
  const Cell target_cell{found % 6, found / 6};
  EXPECT_EQ(target_cell, (Cell{4, 3}));
  std::vector<Cell> path;
  navigator.path(found, &path);
  EXPECT_EQ(path.size(), 10u);
  EXPECT_EQ(path.back(), target_cell);
  EXPECT_TRUE(frontier(target_cell));
  EXPECT_EQ(navigator.firstAction(found), Action::North);
  Cell c{0, 3};
  for (Cell next : path) {
    EXPECT_EQ(std::abs(next.x - c.x) + std::abs(next.y - c.y), 1);
    EXPECT_TRUE(memory.isFree(next));
    c = next;
  }
  // Nothing matching: -1.
  EXPECT_EQ(navigator.search(
                Cell{0, 3}, [&](Cell cell) { return memory.isFree(cell); }, [](Cell) { return false; }),
            -1);
}

TEST(NavigationTest, ReusedNavigatorGivesTheSameAnswers) {
  const AgentMemory memory = drawnMemory({
      "....",
      ".##.",
      "....",
  });
  Navigator navigator;
  navigator.reset(4, 3);
  Action first = Action::Stay;
  ASSERT_TRUE(navigator.towardsGoal(memory, Cell{0, 1}, Cell{3, 1}, &first));
  for (int i = 0; i < 1000; ++i) {
    Action again = Action::Stay;
    ASSERT_TRUE(navigator.towardsGoal(memory, Cell{0, 1}, Cell{3, 1}, &again));
    ASSERT_EQ(again, first);
  }
  EXPECT_EQ(first, Action::North);  // N is expanded first, and both ways round are 5 moves
}

}  // namespace
}  // namespace agents
}  // namespace ppp
