#include "ppp_core/visibility.hpp"

#include <gtest/gtest.h>

#include "grid_picture.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace {

using test::picture;

/// Visible cells drawn as a picture: 'v' visible, '-' hidden.
std::vector<std::string> visibleMap(const Grid& grid, Cell viewpoint) {
  VisibilitySolver solver;
  solver.solve(grid, viewpoint);
  std::vector<std::string> rows;
  for (int y = 0; y < grid.height(); ++y) {
    std::string row;
    for (int x = 0; x < grid.width(); ++x) row += solver.visible()[grid.index(Cell{x, y})] ? 'v' : '-';
    rows.push_back(row);
  }
  return rows;
}

TEST(VisibilityTest, OpenGridSeesEverything) {
  Grid grid(7, 5);
  EXPECT_DOUBLE_EQ(visibilityFraction(grid, Cell{3, 2}), 1.0);
  EXPECT_DOUBLE_EQ(visibilityFraction(grid, Cell{0, 0}), 1.0);
}

TEST(VisibilityTest, WallCastsShadowWorkedByHand) {
  // Viewer at (0,1); the obstacle (1,1) at distance 1 spans slopes (-1, 1) (its corners at (0.5, +-0.5)),
  // so every cell further east with |dy| < dx is hidden; column 1 is nearer than any shadow.
  auto p = picture({
      ".....",
      "S#...",
      ".....",
  });
  EXPECT_EQ(visibleMap(p.grid, p.start), (std::vector<std::string>{"vv---", "vv---", "vv---"}));
}

TEST(VisibilityTest, DiagonalCrackIsSeeThrough) {
  // Two obstacles touching only at a corner do not block the diagonal through that corner.
  auto p = picture({
      "S#.",
      "#..",
      "...",
  });
  VisibilitySolver solver;
  solver.solve(p.grid, p.start);
  EXPECT_TRUE(solver.visible()[p.grid.index(Cell{2, 2})]);
  EXPECT_TRUE(solver.visible()[p.grid.index(Cell{1, 1})]);
  // (2,1): slope 1/2 from (0,0); it crosses cell (1,0)? At x in (0.5,1.5) y in (0.25,0.75): row 0 band is
  // (-0.5, 0.5) -> yes, (1,0) is crossed and it is an obstacle: hidden.
  EXPECT_FALSE(solver.visible()[p.grid.index(Cell{2, 1})]);
  EXPECT_TRUE(lineOfSight(p.grid, p.start, Cell{2, 2}));
  EXPECT_FALSE(lineOfSight(p.grid, p.start, Cell{2, 1}));
}

TEST(VisibilityTest, ObstacleCellsAreSeenButBlockWhatIsBehind) {
  // From (0,0): the obstacle (2,0) is seen and hides (3,0), (4,0) and (4,1) (slope 1/4 inside its shadow
  // (-1/3, 1/3)); (1,1) hides (2,1) (slope 1/2 inside (1/3, 3)); (3,1) at slope exactly 1/3 passes through
  // the corner where the two shadows touch, so it is seen.
  auto p = picture({"S.#..", "##..."});
  EXPECT_EQ(visibleMap(p.grid, p.start), (std::vector<std::string>{"vvv--", "vv-v-"}));
  EXPECT_DOUBLE_EQ(visibilityFraction(p.grid, p.start), 6.0 / 10.0);
}

/// Brute force with exact integers: does the open segment between centres meet the open square of cell c?
bool segmentCrossesCell(Cell a, Cell b, Cell c) {
  // Doubled coordinates: centres at 2x+1; the square of c is (2cx, 2cx+2) x (2cy, 2cy+2).
  const long ax = 2 * a.x + 1, ay = 2 * a.y + 1, dx = 2 * (b.x - a.x), dy = 2 * (b.y - a.y);
  // Parameter t in (0,1) scaled: keep t as a fraction num/den with den = 1 initially; intersect intervals.
  long lo_n = 0, lo_d = 1, hi_n = 1, hi_d = 1;  // open interval (lo, hi) of t
  auto clip = [&](long start, long delta, long min, long max) {
    if (delta == 0) return start > min && start < max;
    long n1 = min - start, n2 = max - start, d = delta;
    if (d < 0) {
      n1 = -n1;
      n2 = -n2;
      d = -d;
      std::swap(n1, n2);
    }
    if (n1 * lo_d > lo_n * d) lo_n = n1, lo_d = d;
    if (n2 * hi_d < hi_n * d) hi_n = n2, hi_d = d;
    return true;
  };
  if (!clip(ax, dx, 2 * c.x, 2 * c.x + 2)) return false;
  if (!clip(ay, dy, 2 * c.y, 2 * c.y + 2)) return false;
  return lo_n * hi_d < hi_n * lo_d;
}

TEST(VisibilityTest, SweepAndLineOfSightMatchBruteForceOnRandomGrids) {
  Rng rng(99);
  VisibilitySolver solver;
  for (int trial = 0; trial < 60; ++trial) {
    const int w = static_cast<int>(rng.uniformInt(2, 14));
    const int h = static_cast<int>(rng.uniformInt(2, 14));
    Grid g(w, h);
    const double density = rng.uniform01() * 0.4;
    for (int i = 0; i < g.size(); ++i) g.setObstacle(g.cellAt(i), rng.bernoulli(density));
    const Cell v{static_cast<int>(rng.below(w)), static_cast<int>(rng.below(h))};
    solver.solve(g, v);
    for (int i = 0; i < g.size(); ++i) {
      const Cell target = g.cellAt(i);
      bool expected = true;
      for (int j = 0; j < g.size() && expected; ++j) {
        const Cell c = g.cellAt(j);
        if (c == v || c == target || !g.isObstacle(c)) continue;
        if (segmentCrossesCell(v, target, c)) expected = false;
      }
      ASSERT_EQ(lineOfSight(g, v, target), expected) << "trial " << trial << " target " << target.x << "," << target.y;
      ASSERT_EQ(solver.visible()[i] != 0, expected) << "trial " << trial << " target " << target.x << "," << target.y;
    }
  }
}

}  // namespace
}  // namespace ppp
