#include "mrpt_grid_planner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "map_picture.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/reachability.hpp"

namespace ppp {
namespace planners {
namespace {

using Picture = std::vector<std::string>;

/// The map-frame centres of cells of a map.
std::vector<MapPoint> centres(const std::vector<Cell>& cells, const GridMap& map) {
  std::vector<MapPoint> points;
  for (const Cell cell : cells) points.push_back(map.centre(cell));
  return points;
}

/// True when the 4-connected robot can walk from S to G.
bool robotCanWalk(const Picture& picture) {
  return fewestMoves(test::pictureGrid(picture), test::markedCell(picture, 'S'), test::markedCell(picture, 'G'),
                     Connectivity::Four) >= 0;
}

void expectSamePoints(const std::vector<MapPoint>& actual, const std::vector<MapPoint>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    EXPECT_NEAR(actual[i].x, expected[i].x, 1e-6) << "waypoint " << i;
    EXPECT_NEAR(actual[i].y, expected[i].y, 1e-6) << "waypoint " << i;
  }
}

// On an open map MRPT's 8-connected wavefront (straight step 2, diagonal 3) takes the diagonal: four diagonal
// steps cost 12, any other route needs at least one straight step pair (4) for each diagonal it drops.
TEST(MrptGridPlannerTest, OpenMapGivesTheDiagonalFromStartCentreToGoalCentre) {
  const Picture picture = {"S....", ".....", ".....", ".....", "....G"};
  for (const double resolution : {1.0, 0.5}) {
    const GridMap map = test::mapPicture(picture, true, resolution);
    const std::vector<MapPoint> path = MrptGridPlanner(0).plan(map, Cell{0, 0}, Cell{4, 4});
    expectSamePoints(path, centres({{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}}, map));
  }
}

// A library fault the hunt can meet: the wavefront never expands through the map's outermost ring, so a route
// the robot walks along the map's edge is no path for MRPT.
TEST(MrptGridPlannerTest, RouteAlongTheMapEdgeIsNoPath) {
  const Picture picture = {"S....", "####.", "####.", "####.", "####G"};
  ASSERT_TRUE(robotCanWalk(picture));
  EXPECT_TRUE(MrptGridPlanner(0).plan(test::mapPicture(picture), Cell{0, 0}, Cell{4, 4}).empty());
  // The same route one cell in from the edge is found.
  const Picture inner = {"#######", "#S....#", "#####.#", "#####.#", "#####G#", "#######"};
  ASSERT_TRUE(robotCanWalk(inner));
  const GridMap map = test::mapPicture(inner);
  expectSamePoints(MrptGridPlanner(0).plan(map, Cell{1, 1}, Cell{5, 4}),
                   centres({{1, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 2}, {5, 3}, {5, 4}}, map));
}

// The other: a diagonal wall, whose cells touch only at corners, stops the 4-connected robot but not MRPT's
// diagonal steps at robot radius 0; a radius of one cell grows the wall shut.
TEST(MrptGridPlannerTest, DiagonalWallIsCrossedAtRadiusZeroOnly) {
  const Picture picture = {"S..#.", "..#..", ".#...", "#....", "....G"};
  ASSERT_FALSE(robotCanWalk(picture));
  const GridMap map = test::mapPicture(picture);
  expectSamePoints(MrptGridPlanner(0).plan(map, Cell{0, 0}, Cell{4, 4}),
                   centres({{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}}, map));
  EXPECT_TRUE(MrptGridPlanner(1).plan(map, Cell{0, 0}, Cell{4, 4}).empty());
}

TEST(MrptGridPlannerTest, ObstacleGoalAndUnknownCellsTakenAsBlockedAreNoPath) {
  const Picture picture = {"S...", "....", "..??", "..?G"};
  EXPECT_TRUE(MrptGridPlanner(0).plan(test::mapPicture(picture, false), Cell{0, 0}, Cell{3, 3}).empty());
  EXPECT_FALSE(MrptGridPlanner(0).plan(test::mapPicture(picture, true), Cell{0, 0}, Cell{3, 3}).empty());
  const Picture walled_goal = {"S...", "....", "....", "...#"};
  EXPECT_TRUE(MrptGridPlanner(0).plan(test::mapPicture(walled_goal), Cell{0, 0}, Cell{3, 3}).empty());
}

TEST(MrptGridPlannerTest, NegativeOrNonFiniteRadiusIsRefusedByName) {
  for (const double radius : {-1.0, std::nan("")}) {
    try {
      MrptGridPlanner planner(radius);
      FAIL() << "accepted robot_radius " << radius;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.name(), "robot_radius");
    }
  }
}

}  // namespace
}  // namespace planners
}  // namespace ppp
