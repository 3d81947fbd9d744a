#include "grid_map.hpp"

#include <gtest/gtest.h>

#include "map_picture.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace planners {
namespace {

TEST(GridMapTest, ReadsOccupancyDataBottomRowFirst) {
  // Data row 0 is the bottom grid row: its last cell (2, 1) is the obstacle; the top-left cell is unknown.
  const std::vector<std::int8_t> data{0, 0, 100, -1, 0, 0};
  const GridMap optimistic(3, 2, 1.0, data, true);
  const GridMap cautious(3, 2, 1.0, data, false);
  EXPECT_FALSE(optimistic.passable(Cell{2, 1}));
  EXPECT_TRUE(optimistic.passable(Cell{2, 0}));
  EXPECT_TRUE(optimistic.passable(Cell{0, 0}));
  EXPECT_FALSE(cautious.passable(Cell{0, 0}));
  EXPECT_TRUE(cautious.passable(Cell{1, 0}));
  EXPECT_FALSE(optimistic.passable(Cell{3, 0}));
  EXPECT_FALSE(optimistic.passable(Cell{0, -1}));
}

TEST(GridMapTest, AnInflationKeepsTheDiscOffKnownObstaclesAndTheEdge) {
  // 5x5, one obstacle in the middle (data is bottom row first; the middle row is row 2 either way). Inflated by
  // 1, a cell is kept when its 3x3 block is on the map and clear of the obstacle: the inner 3x3 cells all touch
  // (2, 2) and the outer ring touches the edge, so nothing is left.
  std::vector<std::int8_t> data(25, 0);
  data[2 * 5 + 2] = 100;
  const GridMap point(5, 5, 1.0, data, true, 0);
  const GridMap disc(5, 5, 1.0, data, true, 1);
  EXPECT_TRUE(point.passable(Cell{1, 1}));
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 5; ++x) EXPECT_FALSE(disc.passable(Cell{x, y})) << x << "," << y;
  }
  // 7x7 with nothing known: the 5x5 inside is left, the unknown corner does not block (1, 1).
  std::vector<std::int8_t> open(49, 0);
  open[6 * 7 + 0] = -1;
  const GridMap room(7, 7, 1.0, open, true, 1);
  EXPECT_TRUE(room.passable(Cell{1, 1}));
  EXPECT_FALSE(room.passable(Cell{0, 3}));
  EXPECT_TRUE(room.passable(Cell{5, 5}));
}

TEST(GridMapTest, HighOccupancyIsAnObstacle) {
  const GridMap map(2, 2, 1.0, {49, 50, 0, 99}, true);
  EXPECT_TRUE(map.passable(Cell{0, 1}));
  EXPECT_FALSE(map.passable(Cell{1, 1}));
  EXPECT_FALSE(map.passable(Cell{1, 0}));
}

TEST(GridMapTest, RefusesMalformedMaps) {
  EXPECT_THROW(GridMap(2, 2, 1.0, {0, 0, 0}, true), InvalidArgument);
  EXPECT_THROW(GridMap(2, 2, 1.0, {0, 0, 0, -2}, true), InvalidArgument);
  EXPECT_THROW(GridMap(2, 2, 0.0, {0, 0, 0, 0}, true), InvalidArgument);
  EXPECT_THROW(GridMap(1, 2, 1.0, {0, 0}, true), InvalidArgument);
  try {
    GridMap(2, 2, 1.0, {0, 0, 101, 0}, true);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "map data[2]");
  }
}

TEST(GridMapTest, PointsAndCentresInMetres) {
  const GridMap map = test::mapPicture({"...", "..."}, true, 0.5);
  EXPECT_EQ(map.cellOf(MapPoint{0.25, 0.75}), (Cell{0, 0}));
  EXPECT_EQ(map.cellOf(MapPoint{1.4, 0.1}), (Cell{2, 1}));
  EXPECT_FALSE(map.contains(map.cellOf(MapPoint{1.6, 0.1})));
  for (const Cell cell : {Cell{0, 0}, Cell{2, 0}, Cell{1, 1}}) EXPECT_EQ(map.cellOf(map.centre(cell)), cell);
  EXPECT_DOUBLE_EQ(map.centre(Cell{2, 0}).x, 1.25);
  EXPECT_DOUBLE_EQ(map.centre(Cell{2, 0}).y, 0.75);
}

TEST(GridMapTest, ASegmentMustBePassableBothWays) {
  // From (0,0)'s centre to (1,1)'s the walk passes the corner by (1,0) (x first); back, by (0,1).
  const GridMap open = test::mapPicture({"..", ".."});
  const GridMap lower_left = test::mapPicture({"..", "#."});
  const GridMap upper_right = test::mapPicture({".#", ".."});
  const MapPoint a = open.centre(Cell{0, 0});
  const MapPoint b = open.centre(Cell{1, 1});
  EXPECT_TRUE(open.segmentPassable(a, b));
  EXPECT_FALSE(lower_left.segmentPassable(a, b));
  EXPECT_FALSE(lower_left.segmentPassable(b, a));
  EXPECT_FALSE(upper_right.segmentPassable(a, b));
  EXPECT_TRUE(upper_right.segmentPassable(a, a));
  EXPECT_FALSE(open.segmentPassable(a, MapPoint{2.5, 1.5}));
}

TEST(GridMapTest, APathPassesTheCellsOfItsSegments) {
  // An L through the centres of (0,0), (3,0) and (3,2) of a 4x3 map: it passes the top row and the right column,
  // and no other cell; a path of one waypoint passes nowhere, not even its own cell.
  const GridMap map = test::mapPicture({"....", "....", "...."});
  const std::vector<MapPoint> path{map.centre(Cell{0, 0}), map.centre(Cell{3, 0}), map.centre(Cell{3, 2})};
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) EXPECT_EQ(map.pathPasses(path, Cell{x, y}), y == 0 || x == 3) << x << "," << y;
  }
  EXPECT_FALSE(map.pathPasses({map.centre(Cell{1, 1})}, Cell{1, 1}));
  EXPECT_FALSE(map.pathPasses({}, Cell{0, 0}));
  EXPECT_THROW(map.pathPasses({MapPoint{0.5, 0.5}, MapPoint{1e300, 0.5}}, Cell{0, 0}), InvalidArgument);
}

}  // namespace
}  // namespace planners
}  // namespace ppp
