#include "ppp_core/barn_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "grid_picture.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/evaluation_json.hpp"

namespace ppp {
namespace {

const double kRoot2 = std::sqrt(2.0);
constexpr double kTolerance = 1e-12;

/// Rays start at a cell's centre; a cell (x, y) spans [x, x+1] x [y, y+1], so in an empty W x H grid the centre
/// of (x, y) is x + 0.5 from the west edge, W - x - 0.5 from the east edge, and so on. Off the grid is obstacle.
std::vector<Cell> emptyGridRoute() { return {Cell{2, 2}, Cell{2, 1}}; }

TEST(BarnMetricsTest, EmptyGridWithDefaultsByHand) {
  const Grid grid(5, 5);
  const BarnMetrics m = barnMetrics(grid, emptyGridRoute());
  ASSERT_TRUE(m.valid);
  // Clearance: (2,2) is 2.5 from every edge; (2,1) is 1.5 from the north edge.
  EXPECT_NEAR(m.closest_obstacle, (2.5 + 1.5) / 2, kTolerance);
  // Visibility, 8 rays. (2,2): four axis rays of 2.5, four diagonals of 2.5*sqrt2 -> 1.25 + 1.25*sqrt2.
  // (2,1): E 2.5, W 2.5, N 1.5, S 3.5; NE and NW leave through the north edge at 1.5*sqrt2, SE and SW through
  // the east and west edges at 2.5*sqrt2 -> (10 + 8*sqrt2) / 8 = 1.25 + sqrt2. Mean 1.25 + 1.125*sqrt2.
  EXPECT_NEAR(m.visibility, 1.25 + 1.125 * kRoot2, kTolerance);
  // Dispersion, 16 rays, blocked when shorter than 3. (2,2): axis rays 2.5 (blocked), 22.5-degree rays leave at
  // 2.5/cos(22.5) = 2.71 (blocked), diagonals 3.54 (open): four isolated open rays, 8 changes.
  // (2,1): the rays from 225 to 315 degrees (south-west to south-east) are open: 3.54, 3.79, 3.5, 3.79, 3.54;
  // 202.5 and 337.5 leave through the side edges at 2.71 and every northern ray is shorter: 2 changes. Mean 5.
  EXPECT_NEAR(m.dispersion, 5.0, kTolerance);
  // Characteristic dimension, axes 0, 45, 90, 135 degrees. (2,2): chords 5, 5*sqrt2, 5, 5*sqrt2 -> 5.
  // (2,1): horizontal 2.5 + 2.5, vertical 1.5 + 3.5, both diagonals 1.5*sqrt2 + 2.5*sqrt2 = 5.66 -> 5.
  EXPECT_NEAR(m.characteristic_dimension, 5.0, kTolerance);
  // One step between neighbours one apart.
  EXPECT_NEAR(m.tortuosity, 1.0, kTolerance);
}

/// A one-cell corridor along row 1 of a 5x3 grid, walls above and below.
test::Picture corridor() {
  return test::picture({
      "#####",
      "S...G",
      "#####",
  });
}

std::vector<Cell> corridorRoute() { return {Cell{0, 1}, Cell{1, 1}, Cell{2, 1}, Cell{3, 1}, Cell{4, 1}}; }

TEST(BarnMetricsTest, CorridorByHand) {
  const BarnMetrics m = barnMetrics(corridor().grid, corridorRoute());
  // Every cell touches the walls above and below: clearance 0.5.
  EXPECT_NEAR(m.closest_obstacle, 0.5, kTolerance);
  // Cell x: E 4.5 - x, W x + 0.5, N and S 0.5, the four diagonals cross a corner into a wall at 0.5*sqrt2:
  // (6 + 2*sqrt2) / 8 at every cell.
  EXPECT_NEAR(m.visibility, 0.75 + 0.25 * kRoot2, kTolerance);
  // Only the east and west rays can reach 3 (every other ray meets a wall within 0.5/sin(22.5) = 1.31).
  // East open for x <= 1 (4.5 - x >= 3), west open for x >= 3: cells 0, 1, 3, 4 have one open ray (2 changes),
  // cell 2 none: 8 / 5.
  EXPECT_NEAR(m.dispersion, 1.6, kTolerance);
  // The vertical chord is the corridor's width, 0.5 + 0.5; horizontal 5, diagonals sqrt2.
  EXPECT_NEAR(m.characteristic_dimension, 1.0, kTolerance);
  EXPECT_NEAR(m.tortuosity, 1.0, kTolerance);
}

TEST(BarnMetricsTest, OptionsChooseTheRays) {
  BarnOptions o;
  o.visibility_rays = 4;
  o.dispersion_rays = 4;
  o.dispersion_radius = 1;
  o.dimension_axes = 1;
  const BarnMetrics m = barnMetrics(corridor().grid, corridorRoute(), o);
  // Rays E, N, W, S: (4.5 - x + x + 0.5 + 0.5 + 0.5) / 4 = 1.5 at every cell.
  EXPECT_NEAR(m.visibility, 1.5, kTolerance);
  // Radius 1: N and S blocked everywhere; E blocked only at x = 4 (0.5), W only at x = 0.
  // Cells 0 and 4: one open ray, 2 changes; cells 1-3: E and W open, 4 changes. (2 + 4 + 4 + 4 + 2) / 5.
  EXPECT_NEAR(m.dispersion, 3.2, kTolerance);
  // One axis, the horizontal: the corridor's length.
  EXPECT_NEAR(m.characteristic_dimension, 5.0, kTolerance);
  o.dimension_axes = 2;  // horizontal and vertical: the width
  EXPECT_NEAR(barnMetrics(corridor().grid, corridorRoute(), o).characteristic_dimension, 1.0, kTolerance);
}

TEST(BarnMetricsTest, ClearanceAndTortuosityAroundOneObstacleByHand) {
  const Grid grid = test::picture({
                                      ".....",
                                      ".....",
                                      "..#..",
                                      ".....",
                                      ".....",
                                  })
                        .grid;
  const std::vector<Cell> route{{1, 1}, {2, 1}, {3, 1}, {3, 2}, {3, 3}};
  const BarnMetrics m = barnMetrics(grid, route);
  // (1,1), (3,1), (3,3) are diagonal to the obstacle: centre to its corner sqrt(0.5^2 + 0.5^2) = sqrt2/2 (the edges
  // are 1.5 away); (2,1) and (3,2) are beside it: 0.5.
  EXPECT_NEAR(m.closest_obstacle, (3 * kRoot2 / 2 + 2 * 0.5) / 5, kTolerance);
  // Four unit steps from (1,1) to (3,3), 2*sqrt2 apart.
  EXPECT_NEAR(m.tortuosity, 4 / (2 * kRoot2), kTolerance);
}

TEST(BarnMetricsTest, GrazingACornerDoesNotStopARay) {
  const Grid grid = test::picture({
                                      "....",
                                      "..#.",
                                      ".#..",
                                      "....",
                                  })
                        .grid;
  const BarnMetrics m = barnMetrics(grid, {Cell{0, 0}, Cell{1, 0}});
  // (0,0): E 3.5, W 0.5, N 0.5, S 3.5; NE, NW, SW leave the grid at 0.5*sqrt2; SE passes between (2,1) and (1,2),
  // which touch only at a corner, and leaves at (4,4): 3.5*sqrt2. Sum 8 + 5*sqrt2.
  // (1,0): E 2.5, W 1.5, N 0.5, S 1.5 (into (1,2)); NE, NW 0.5*sqrt2 (off the grid), SE 0.5*sqrt2 (into (2,1)),
  // SW through (0,1) and off at 1.5*sqrt2. Sum 6 + 3*sqrt2. Mean over both: (14 + 8*sqrt2) / 16.
  EXPECT_NEAR(m.visibility, 0.875 + 0.5 * kRoot2, kTolerance);
}

TEST(BarnMetricsTest, RangeCapsEveryRayAndTheClearance) {
  BarnOptions o;
  o.range = 1;
  const BarnMetrics m = barnMetrics(Grid(5, 5), emptyGridRoute(), o);
  // Every obstacle and edge is at least 1.5 away from both cells, so every length is cut to 1.
  EXPECT_NEAR(m.closest_obstacle, 1.0, kTolerance);
  EXPECT_NEAR(m.visibility, 1.0, kTolerance);
  EXPECT_NEAR(m.characteristic_dimension, 2.0, kTolerance);
  // Nothing is seen within the range, so no ray is blocked: no change.
  EXPECT_NEAR(m.dispersion, 0.0, kTolerance);
}

TEST(BarnMetricsTest, ProblemUsesTheDpaRoute) {
  const test::Picture c = corridor();
  const Problem problem = problemFromGrid(c.grid, c.start, c.goal);
  // The only route is the corridor itself.
  const BarnMetrics expected = barnMetrics(c.grid, corridorRoute());
  const BarnMetrics m = barnMetrics(problem, c.grid);
  ASSERT_TRUE(m.valid);
  EXPECT_EQ(barnCharacterVector(m), barnCharacterVector(expected));

  const test::Picture walled = test::picture({
      "S#..",
      "##..",
      "...G",
  });
  const BarnMetrics none = barnMetrics(problemFromGrid(walled.grid, walled.start, walled.goal), walled.grid);
  EXPECT_FALSE(none.valid);
  EXPECT_EQ(barnCharacterVector(none), std::vector<double>(5, 0.0));
}

TEST(BarnMetricsTest, RejectsBadOptionsNamingThem) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double infinity = std::numeric_limits<double>::infinity();
  const std::vector<std::pair<std::string, std::function<void(BarnOptions&)>>> cases = {
      {"visibility_rays", [](BarnOptions& o) { o.visibility_rays = 0; }},
      {"visibility_rays", [](BarnOptions& o) { o.visibility_rays = kMaxBarnRays + 1; }},
      {"dispersion_rays", [](BarnOptions& o) { o.dispersion_rays = 0; }},
      {"dimension_axes", [](BarnOptions& o) { o.dimension_axes = -1; }},
      {"dispersion_radius", [](BarnOptions& o) { o.dispersion_radius = 0; }},
      {"dispersion_radius", [nan](BarnOptions& o) { o.dispersion_radius = nan; }},
      {"dispersion_radius", [infinity](BarnOptions& o) { o.dispersion_radius = infinity; }},
      {"range", [](BarnOptions& o) { o.range = -1; }},
      {"range", [](BarnOptions& o) { o.range = 0; }},
      {"range", [nan](BarnOptions& o) { o.range = nan; }},
  };
  const test::Picture walled = test::picture({"S#", "#G"});  // options are checked before the route is sought
  const Problem unreachable = problemFromGrid(walled.grid, walled.start, walled.goal);
  for (const auto& [name, spoil] : cases) {
    BarnOptions o;
    spoil(o);
    try {
      barnMetrics(unreachable, walled.grid, o);
      ADD_FAILURE() << "accepted a bad " << name;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.name(), name);
    }
  }
  BarnOptions limits;
  limits.visibility_rays = limits.dispersion_rays = limits.dimension_axes = 1;
  limits.range = 1e-9;
  EXPECT_NO_THROW(limits.validate());
}

TEST(BarnMetricsTest, RejectsBadRoutes) {
  const Grid grid = corridor().grid;
  const std::vector<std::vector<Cell>> routes = {
      {}, {{1, 1}}, {{0, 1}, {0, 0}}, {{4, 1}, {5, 1}}, {{1, 1}, {2, 1}, {1, 1}},
  };
  for (const auto& route : routes) {
    try {
      barnMetrics(grid, route);
      ADD_FAILURE() << "accepted a route of " << route.size() << " cells";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.name(), "route");
    }
  }
}

TEST(BarnMetricsTest, CharactersAndJson) {
  EXPECT_EQ(barnCharacterNames(),
            (std::vector<std::string>{"barn_closest_obstacle", "barn_visibility", "barn_dispersion",
                                      "barn_characteristic_dimension", "barn_tortuosity"}));
  BarnMetrics m{true, 1, 2, 3, 4, 5};
  EXPECT_EQ(barnCharacterVector(m), (std::vector<double>{1, 2, 3, 4, 5}));
  EXPECT_EQ(barnMetricsToJson(m).dump(),
            R"({"characteristic_dimension":4.0,"closest_obstacle":1.0,"dispersion":3.0,"tortuosity":5.0,)"
            R"("visibility":2.0})");
  m.valid = false;
  EXPECT_EQ(barnMetricsToJson(m).dump(),
            R"({"characteristic_dimension":null,"closest_obstacle":null,"dispersion":null,"tortuosity":null,)"
            R"("visibility":null})");
}

}  // namespace
}  // namespace ppp
