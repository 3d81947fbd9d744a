#include "ppp_core/shrink.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "ppp_core/random_problem.hpp"
#include "ppp_core/reachability.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace {

/// A predicate that holds when every one of `cells` is an obstacle and the goal is reachable.
StillFails obstaclesAt(const std::vector<Cell>& cells) {
  return [cells](const Problem& p) {
    const Grid grid = decodeGrid(p);
    for (const Cell c : cells) {
      if (!grid.isObstacle(c)) return false;
    }
    return isReachable(grid, p.start, p.goal);
  };
}

/// True when `still_fails` holds for `p` and for no PPP with one descriptor fewer or one descriptor a cell smaller.
bool oneMinimal(const Problem& p, const StillFails& still_fails) {
  if (!still_fails(p)) return false;
  for (std::size_t i = 0; i < p.obstacles.size(); ++i) {
    Problem fewer = p;
    fewer.obstacles.erase(fewer.obstacles.begin() + static_cast<std::ptrdiff_t>(i));
    if (still_fails(fewer)) return false;
    for (const Obstacle& smaller : smallerObstacles(p.obstacles[i])) {
      if (smaller.x >= p.width || smaller.y < 0) continue;
      Problem q = p;
      q.obstacles[i] = smaller;
      if (still_fails(q)) return false;
    }
  }
  return true;
}

TEST(ShrinkTest, SmallerObstaclesLoseOneCellAtEitherEndOrSide) {
  const std::vector<Obstacle> bar = smallerObstacles(Obstacle{Shape::DiagonalUp, 3, 5, 4, 1});
  ASSERT_EQ(bar.size(), 2u);
  EXPECT_EQ(bar[0], (Obstacle{Shape::DiagonalUp, 3, 5, 3, 1}));  // without (6, 2)
  EXPECT_EQ(bar[1], (Obstacle{Shape::DiagonalUp, 4, 4, 3, 1}));  // without the anchor (3, 5)
  const std::vector<Obstacle> block = smallerObstacles(Obstacle{Shape::Block, 2, 2, 3, 2});
  ASSERT_EQ(block.size(), 4u);
  EXPECT_EQ(block[1], (Obstacle{Shape::Block, 3, 2, 2, 2}));
  EXPECT_EQ(block[3], (Obstacle{Shape::Block, 2, 3, 3, 1}));
  EXPECT_TRUE(smallerObstacles(Obstacle{Shape::VerticalBar, 0, 0, 1, 1}).empty());
}

TEST(ShrinkTest, DescriptorsThatDoNotMatterGoAndTheRestShrinkToTheCellsThatDo) {
  // The failure needs obstacles at (5, 5) and (7, 7). Worked by hand: the block and the diagonal go, the
  // horizontal bar through (5, 5) shrinks to that cell, the vertical bar through (7, 7) to that one.
  Problem p = Problem::empty(12, 12, 10);
  p.obstacles = {{Shape::Block, 1, 8, 3, 2}, {Shape::HorizontalBar, 0, 5, 10, 1}, {Shape::DiagonalDown, 9, 1, 2, 1},
                 {Shape::VerticalBar, 7, 1, 9, 1}};
  setMetadata(&p.metadata, "id", "ppp_007");
  const StillFails fails = obstaclesAt({{5, 5}, {7, 7}});
  const ShrinkResult r = shrinkProblem(p, fails, ShrinkUnits::Descriptors);
  EXPECT_EQ(r.problem.obstacles,
            (std::vector<Obstacle>{{Shape::HorizontalBar, 5, 5, 1, 1}, {Shape::VerticalBar, 7, 7, 1, 1}}));
  EXPECT_EQ(r.problem.metadata, p.metadata);
  EXPECT_EQ(r.problem.max_obstacles, 10);
  EXPECT_GT(r.evaluations, 4);
  EXPECT_TRUE(oneMinimal(r.problem, fails));
  // The same input gives the same result.
  EXPECT_EQ(shrinkProblem(p, fails, ShrinkUnits::Descriptors).problem, r.problem);
}

TEST(ShrinkTest, ResultsAreOneMinimalOnRandomProblemsAndPredicates) {
  // Predicate: at least k obstacle cells inside a window, the goal still reachable. A brute force over every
  // single removal and every one-cell-smaller descriptor checks each result.
  Rng rng(11);
  int checked = 0;
  for (int round = 0; round < 40; ++round) {
    const Problem p = randomProblem(rng, Problem::empty(16, 16, 12), 12);
    const Cell corner{static_cast<int>(rng.below(10)), static_cast<int>(rng.below(10))};
    const Grid grid = decodeGrid(p);
    int inside = 0;
    for (int y = corner.y; y < corner.y + 6; ++y) {
      for (int x = corner.x; x < corner.x + 6; ++x) inside += grid.isObstacle(Cell{x, y}) ? 1 : 0;
    }
    if (inside == 0) continue;
    const int needed = 1 + static_cast<int>(rng.below(static_cast<std::uint64_t>(inside)));
    const StillFails fails = [&](const Problem& q) {
      const Grid g = decodeGrid(q);
      int n = 0;
      for (int y = corner.y; y < corner.y + 6; ++y) {
        for (int x = corner.x; x < corner.x + 6; ++x) n += g.isObstacle(Cell{x, y}) ? 1 : 0;
      }
      return n >= needed && isReachable(g, q.start, q.goal);
    };
    const ShrinkResult r = shrinkProblem(p, fails, ShrinkUnits::Descriptors);
    EXPECT_TRUE(oneMinimal(r.problem, fails)) << "round " << round;
    EXPECT_LE(r.problem.obstacles.size(), p.obstacles.size());
    EXPECT_LE(decodeGrid(r.problem).obstacleCount(), grid.obstacleCount());
    ++checked;
  }
  EXPECT_GE(checked, 30) << "too many rounds without an obstacle in their window";
}

TEST(ShrinkTest, CellsShrinkByComponentsThenSingleCells) {
  // Three components; the failure needs (3, 3) and (3, 4) of the middle one. Worked by hand: the others go,
  // then every other cell of the middle one.
  Grid grid(10, 10);
  for (const Cell c : std::vector<Cell>{{0, 8}, {1, 8}, {3, 2}, {3, 3}, {3, 4}, {4, 4}, {8, 1}}) grid.setObstacle(c, true);
  Problem p = problemFromGrid(grid, Cell{0, 0}, Cell{9, 9});
  const StillFails fails = obstaclesAt({{3, 3}, {3, 4}});
  const ShrinkResult r = shrinkProblem(p, fails, ShrinkUnits::Cells);
  const Grid shrunk = decodeGrid(r.problem);
  EXPECT_EQ(shrunk.obstacleCount(), 2);
  EXPECT_TRUE(shrunk.isObstacle(Cell{3, 3}));
  EXPECT_TRUE(shrunk.isObstacle(Cell{3, 4}));
  // Removing either cell ends the failure: 1-minimal over cells.
  for (const Cell c : std::vector<Cell>{{3, 3}, {3, 4}}) {
    Grid fewer = shrunk;
    fewer.setObstacle(c, false);
    EXPECT_FALSE(fails(problemFromGrid(fewer, p.start, p.goal)));
  }
}

TEST(ShrinkTest, APppThatDoesNotFailIsRefusedAndAStopIsObeyed) {
  Problem p = Problem::empty(8, 8, 4);
  p.obstacles = {{Shape::HorizontalBar, 0, 3, 5, 1}};
  try {
    shrinkProblem(p, obstaclesAt({{7, 3}}), ShrinkUnits::Descriptors);
    ADD_FAILURE() << "shrank a PPP that does not fail";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "problem");
  }
  int asked = 0;
  EXPECT_THROW(shrinkProblem(p, obstaclesAt({{2, 3}}), ShrinkUnits::Descriptors, [&] { return ++asked > 3; }),
               Interrupted);
}

}  // namespace
}  // namespace ppp
