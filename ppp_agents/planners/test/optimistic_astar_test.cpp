#include "optimistic_astar.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <deque>
#include <string>
#include <vector>

#include "map_picture.hpp"

namespace ppp {
namespace planners {
namespace {

using Cells = std::vector<Cell>;
using Picture = std::vector<std::string>;

/// Breadth-first distance in steps through passable cells, or -1: the shortest-path length A* must match.
int bfsDistance(const GridMap& map, Cell start, Cell goal) {
  const int width = map.frame().width;
  std::vector<int> distance(static_cast<std::size_t>(width * map.frame().height), -1);
  std::deque<Cell> queue{start};
  distance[static_cast<std::size_t>(start.y * width + start.x)] = 0;
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    for (const Cell n : {Cell{c.x + 1, c.y}, Cell{c.x - 1, c.y}, Cell{c.x, c.y + 1}, Cell{c.x, c.y - 1}}) {
      if (!map.passable(n) || distance[static_cast<std::size_t>(n.y * width + n.x)] >= 0) continue;
      distance[static_cast<std::size_t>(n.y * width + n.x)] = distance[static_cast<std::size_t>(c.y * width + c.x)] + 1;
      queue.push_back(n);
    }
  }
  return distance[static_cast<std::size_t>(goal.y * width + goal.x)];
}

/// Plans S -> G on a drawn map and checks the path is a shortest walk through passable cells.
Cells checkedPlan(const Picture& picture) {
  const GridMap map = test::mapPicture(picture);
  const Cell start = test::markedCell(picture, 'S');
  const Cell goal = test::markedCell(picture, 'G');
  const Cells path = optimisticAStar(map, start, goal);
  const int distance = bfsDistance(map, start, goal);
  if (distance < 0) {
    EXPECT_TRUE(path.empty());
    return path;
  }
  EXPECT_EQ(static_cast<int>(path.size()), distance + 1);
  if (path.empty()) return path;
  EXPECT_EQ(path.front(), start);
  EXPECT_EQ(path.back(), goal);
  for (std::size_t i = 1; i < path.size(); ++i) {
    EXPECT_TRUE(map.passable(path[i])) << "cell " << i;
    EXPECT_EQ(std::abs(path[i].x - path[i - 1].x) + std::abs(path[i].y - path[i - 1].y), 1) << "step " << i;
  }
  return path;
}

TEST(OptimisticAStarTest, OpenMapPathIsShortestWithFixedTieBreaking) {
  EXPECT_EQ(checkedPlan({"S..", "...", "..G"}), (Cells{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}}));
  EXPECT_EQ(checkedPlan({"S..", "...", "..G"}), checkedPlan({"S..", "...", "..G"}));
  EXPECT_EQ(checkedPlan({"SG", ".."}), (Cells{{0, 0}, {1, 0}}));
}

TEST(OptimisticAStarTest, FindsTheBreadthFirstShortestPathAroundWalls) {
  checkedPlan({
      "S.#.....",
      ".##.###.",
      "....#...",
      "###.#.#.",
      "....#.#G",
  });
  checkedPlan({
      "S#......",
      ".#.####.",
      ".#.#..#.",
      ".#.#G.#.",
      ".#.##.#.",
      "...##...",
  });
  EXPECT_EQ(checkedPlan({"G.S", "..."}), (Cells{{2, 0}, {1, 0}, {0, 0}}));
}

TEST(OptimisticAStarTest, PassesThroughUnknownCells) {
  const Cells path = checkedPlan({
      "S.#..",
      "..#..",
      "..?.G",
  });
  ASSERT_FALSE(path.empty());
  EXPECT_NE(std::find(path.begin(), path.end(), Cell{2, 2}), path.end());
}

TEST(OptimisticAStarTest, NoPathWhenWalledIn) {
  EXPECT_TRUE(checkedPlan({"S.#..", "..#.G", "..#.."}).empty());
  EXPECT_TRUE(checkedPlan({"S....", "...#.", "..#G#"}).empty());
  EXPECT_TRUE(checkedPlan({"S..#G", "...#."}).empty());
}

TEST(OptimisticAStarTest, RefusesGoalsItCannotReach) {
  const GridMap map = test::mapPicture({"...", ".#."});
  EXPECT_TRUE(optimisticAStar(map, Cell{0, 0}, Cell{1, 1}).empty());
  EXPECT_TRUE(optimisticAStar(map, Cell{0, 0}, Cell{3, 0}).empty());
  EXPECT_TRUE(optimisticAStar(map, Cell{-1, 0}, Cell{2, 0}).empty());
  EXPECT_EQ(optimisticAStar(map, Cell{2, 1}, Cell{2, 1}), (Cells{{2, 1}}));
}

TEST(OptimisticAStarTest, ReplansAroundANewlyKnownWall) {
  // First plan: straight through the unknown cell; once the map shows a wall there, around it.
  const Cells first = checkedPlan({
      "S.?.G",
      "..?..",
      ".....",
  });
  ASSERT_EQ(first.size(), 5u);
  EXPECT_EQ(first[2], (Cell{2, 0}));
  const Cells second = checkedPlan({
      "S.#.G",
      "..#..",
      ".....",
  });
  ASSERT_EQ(second.size(), 9u);
  for (const Cell cell : second) EXPECT_FALSE(cell.x == 2 && cell.y < 2) << cell.x << ", " << cell.y;
}

}  // namespace
}  // namespace planners
}  // namespace ppp
