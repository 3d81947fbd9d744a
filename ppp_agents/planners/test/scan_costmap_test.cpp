// The DWA example's memory and route costs on maps small enough to work out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ppp_core/error.hpp"
#include "scan_costmap.hpp"

namespace ppp {
namespace planners {
namespace {

TEST(ScanCostmapTest, InTheOpenTheCostIsTheRoutesLength) {
  // A strip of four 1 m cells, the goal in the last: 3 m from the first cell's centre.
  ScanCostmap costmap(4, 1, {0, 0}, 1.0, 0, 0);
  costmap.plan({3.5, 0.5});
  EXPECT_DOUBLE_EQ(costmap.distance({0.5, 0.5}), 3);
  EXPECT_DOUBLE_EQ(costmap.distance({1.5, 0.5}), 2);
  EXPECT_EQ(costmap.distance({-0.5, 0.5}), std::numeric_limits<double>::infinity());  // off the map
}

TEST(ScanCostmapTest, AMarkedWallIsGoneAroundWithoutCuttingItsCorners) {
  // 5 x 3 cells of 1 m; two returns on the face x = 2, seen from (0.5, 0.5), mark cells (2, 0) and (2, 1). From
  // (0, 0) to the goal (4, 0) the route climbs to row 2 and back without cutting a marked cell's corner:
  // (0,0) -> (1,1) diagonal, (1,2), (2,2), (3,2) straight, (4,1) diagonal, (4,0) straight: 4 + 2 sqrt(2).
  ScanCostmap costmap(5, 3, {0, 0}, 1.0, 0, 0);
  costmap.mark({0.5, 0.5}, {{2.0, 0.5}, {2.0, 1.5}});
  costmap.plan({4.5, 0.5});
  EXPECT_NEAR(costmap.distance({0.5, 0.5}), 4 + 2 * std::sqrt(2.0), 1e-12);
  // The other side of the wall is near: (3, 0) is 1 m from the goal.
  EXPECT_NEAR(costmap.distance({3.5, 0.5}), 1, 1e-12);
}

TEST(ScanCostmapTest, AReturnOnACellsCornerMarksNothing) {
  // The beam may have passed between two cells touching there: which it hit is unknown.
  ScanCostmap costmap(4, 2, {0, 0}, 1.0, 0, 0);
  costmap.mark({0.5, 0.5}, {{2.0, 1.0}});
  costmap.plan({3.5, 0.5});
  EXPECT_DOUBLE_EQ(costmap.distance({0.5, 0.5}), 3);
}

TEST(ScanCostmapTest, InflationMakesCellsNearAWallDearerAndTheRadiusMakesThemLethal) {
  // A corridor of 5 x 3 cells of 1 m, a wall marked along its bottom row (returns on the face y = 1 seen from
  // above); from (0.5, 1.5) to the goal (4.5, 1.5) along the middle row.
  const auto corridor = [](double radius, double inflation) {
    ScanCostmap costmap(5, 3, {0, 0}, 1.0, radius, inflation);
    costmap.mark({2.5, 2.5}, {{0.5, 1.0}, {1.5, 1.0}, {2.5, 1.0}, {3.5, 1.0}, {4.5, 1.0}});
    costmap.plan({4.5, 1.5});
    return costmap.distance({0.5, 1.5});
  };
  // No inflation: the middle row's length.
  EXPECT_DOUBLE_EQ(corridor(0, 0), 4);
  // An inflation radius of 2 m: a middle-row cell (0.5 m from the wall) weighs 1 + 4 (1 - 0.5 / 2) = 4, a top-row
  // cell (1.5 m) 1 + 4 (1 - 1.5 / 2) = 2, a step the mean of its two cells' weights times its length. Along the
  // middle row 4 x 4 = 16; the top cell (1, 2) is 2 x 2 + 3 sqrt(2) from the goal (two top steps, one diagonal
  // down), and the point a straight sqrt(2) from it: 4 + 4 sqrt(2), the least.
  EXPECT_NEAR(corridor(0, 2), 4 + 4 * std::sqrt(2.0), 1e-9);
  // A radius of 0.6 m makes the middle row lethal (and cuts the diagonals through it): the goal is reached from
  // (4, 2) above it, so (1, 2) is 1 + 3 from it, the point sqrt(2) from (1, 2).
  EXPECT_NEAR(corridor(0.6, 0.6), 4 + std::sqrt(2.0), 1e-9);
}

TEST(ScanCostmapTest, ACostmapWithNoCellsOrTooManyIsRefusedNamingItsResolution) {
  for (double resolution : {0.0, -1.0, 1e-6}) {
    try {
      ScanCostmap(20, 20, {0, 0}, resolution, 0, 0.5);
      ADD_FAILURE() << "accepted a resolution of " << resolution;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.name(), "costmap_resolution");
    }
  }
}

}  // namespace
}  // namespace planners
}  // namespace ppp
