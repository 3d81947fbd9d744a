#include "ppp_core/dpa.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>

#include "grid_picture.hpp"
#include "ppp_core/random_problem.hpp"

namespace ppp {
namespace {

using test::picture;

TEST(DpaTest, StraightCorridor) {
  // Four advances east, no turn: the start heading is free.
  auto p = picture({"S...G", "#####"});
  const DpaResult r = solveDpa(p.grid, p.start, p.goal);
  ASSERT_TRUE(r.reachable);
  EXPECT_EQ(r.turns, 0);
  EXPECT_EQ(r.advances, 4);
  EXPECT_EQ(r.turns_plus_advances, 4);
  EXPECT_EQ(r.route.size(), 5u);
  EXPECT_EQ(r.start_heading, Heading::East);
}

TEST(DpaTest, OneBend) {
  // Corner to corner of an open 3x3: 4 advances, 1 turn, 5 together.
  auto p = picture({"S..", "...", "..G"});
  const DpaResult r = solveDpa(p.grid, p.start, p.goal);
  EXPECT_EQ(r.turns, 1);
  EXPECT_EQ(r.advances, 4);
  EXPECT_EQ(r.turns_plus_advances, 5);
}

TEST(DpaTest, Spiral) {
  // The only route: E6, S6, W6, N4, E4, S2, W2 = 30 advances and 6 turns.
  auto p = picture({
      "S......",
      "######.",
      ".....#.",
      ".###.#.",
      ".#G..#.",
      ".#####.",
      ".......",
  });
  const DpaResult r = solveDpa(p.grid, p.start, p.goal);
  ASSERT_TRUE(r.reachable);
  EXPECT_EQ(r.advances, 30);
  EXPECT_EQ(r.turns, 6);
  EXPECT_EQ(r.turns_plus_advances, 36);
  EXPECT_EQ(r.route.size(), 31u);
}

TEST(DpaTest, TurnsAndAdvancesComeFromDifferentRoutes) {
  // Wiggle under the block at (2,3): E1 S1 E2 N1 E2 = 7 advances with 4 turns (11 together).
  // Round the top: N3 E5 S3 = 11 advances with 2 turns (13 together). No route has fewer than
  // 2 turns (start and goal share a row that is blocked), none fewer than 7 advances (Manhattan 5
  // plus the forced detour of 2).
  auto p = picture({
      "......",
      ".####.",
      ".####.",
      "S.#..G",
      "#...##",
  });
  const DpaResult r = solveDpa(p.grid, p.start, p.goal);
  EXPECT_EQ(r.turns, 2);
  EXPECT_EQ(r.advances, 7);
  EXPECT_EQ(r.turns_plus_advances, 11);
  const std::vector<Cell> wiggle{{0, 3}, {1, 3}, {1, 4}, {2, 4}, {3, 4}, {3, 3}, {4, 3}, {5, 3}};
  EXPECT_EQ(r.route, wiggle);
  EXPECT_EQ(r.start_heading, Heading::East);
}

TEST(DpaTest, UnreachableGoal) {
  auto p = picture({"S..#.", "...#G", "...#."});
  const DpaResult r = solveDpa(p.grid, p.start, p.goal);
  EXPECT_FALSE(r.reachable);
  EXPECT_EQ(r.turns, -1);
  EXPECT_EQ(r.advances, -1);
  EXPECT_EQ(r.turns_plus_advances, -1);
  EXPECT_TRUE(r.route.empty());
}

/// Independent reference: Bellman-Ford relaxation of every state until nothing changes.
int bruteForce(const Grid& g, Cell start, Cell goal, int turn_cost, int advance_cost) {
  const int inf = std::numeric_limits<int>::max() / 2;
  const int dx[4] = {0, 1, 0, -1};
  const int dy[4] = {-1, 0, 1, 0};
  std::vector<int> cost(static_cast<std::size_t>(g.size()) * 4, inf);
  for (int h = 0; h < 4; ++h) cost[g.index(start) * 4 + h] = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (int i = 0; i < g.size(); ++i) {
      const Cell c = g.cellAt(i);
      if (!g.isFree(c)) continue;
      for (int h = 0; h < 4; ++h) {
        const int here = cost[i * 4 + h];
        if (here >= inf) continue;
        auto relax = [&](int state, int value) {
          if (value < cost[state]) {
            cost[state] = value;
            changed = true;
          }
        };
        relax(i * 4 + (h + 1) % 4, here + turn_cost);
        relax(i * 4 + (h + 3) % 4, here + turn_cost);
        const Cell n{c.x + dx[h], c.y + dy[h]};
        if (g.isFree(n)) relax(g.index(n) * 4 + h, here + advance_cost);
      }
    }
  }
  int best = inf;
  for (int h = 0; h < 4; ++h) best = std::min(best, cost[g.index(goal) * 4 + h]);
  return best >= inf ? -1 : best;
}

/// Turns plus advances needed to follow a route of adjacent cells, starting in `heading`.
int routeCost(const std::vector<Cell>& route, Heading heading) {
  int h = static_cast<int>(heading);
  int cost = 0;
  for (std::size_t i = 1; i < route.size(); ++i) {
    const int dx = route[i].x - route[i - 1].x;
    const int dy = route[i].y - route[i - 1].y;
    EXPECT_EQ(std::abs(dx) + std::abs(dy), 1) << "route cells not adjacent at step " << i;
    const int want = dy < 0 ? 0 : dx > 0 ? 1 : dy > 0 ? 2 : 3;
    const int diff = (want - h + 4) % 4;
    cost += diff == 2 ? 2 : (diff == 0 ? 0 : 1);
    h = want;
    cost += 1;
  }
  return cost;
}

TEST(DpaTest, MatchesBruteForceOnRandomGrids) {
  Rng rng(12345);
  DpaSolver solver;
  int reachable = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int w = static_cast<int>(rng.uniformInt(2, 9));
    const int h = static_cast<int>(rng.uniformInt(2, 9));
    Grid g(w, h);
    const double density = rng.uniform01() * 0.45;
    for (int i = 0; i < g.size(); ++i) g.setObstacle(g.cellAt(i), rng.bernoulli(density));
    const Cell start{static_cast<int>(rng.below(w)), static_cast<int>(rng.below(h))};
    Cell goal = start;
    while (goal == start) goal = Cell{static_cast<int>(rng.below(w)), static_cast<int>(rng.below(h))};
    g.setObstacle(start, false);
    g.setObstacle(goal, false);
    const DpaResult& r = solver.solve(g, start, goal);
    EXPECT_EQ(r.turns, bruteForce(g, start, goal, 1, 0)) << "trial " << trial;
    EXPECT_EQ(r.advances, bruteForce(g, start, goal, 0, 1)) << "trial " << trial;
    EXPECT_EQ(r.turns_plus_advances, bruteForce(g, start, goal, 1, 1)) << "trial " << trial;
    EXPECT_EQ(r.reachable, r.advances >= 0);
    if (!r.reachable) continue;
    ++reachable;
    ASSERT_GE(r.route.size(), 2u);
    EXPECT_EQ(r.route.front(), start);
    EXPECT_EQ(r.route.back(), goal);
    for (Cell c : r.route) EXPECT_TRUE(g.isFree(c));
    EXPECT_EQ(routeCost(r.route, r.start_heading), r.turns_plus_advances) << "trial " << trial;
  }
  EXPECT_GT(reachable, 150);
}

}  // namespace
}  // namespace ppp
