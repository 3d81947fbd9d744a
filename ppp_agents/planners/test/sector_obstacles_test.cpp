// Obstacle distances per sector as mrpt_reactive_node gives them to MRPT's holonomic methods: the nearest ray for a
// point, a disc's travel for a body (checked against MRPT's own straight trajectories for a round robot,
// CPTG_Holo_Blend at rest), and casts on the robot's map.
#include "sector_obstacles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "holo_blend.hpp"
#include "map_picture.hpp"

namespace ppp {
namespace planners {
namespace {

constexpr int kRays = 72;  // as the planner bridge's LaserScan on the grid
constexpr float kNoReturn = std::numeric_limits<float>::infinity();

// Sector k spans [-180° + 5k, -175° + 5k]: a ray at 0° lies on the border of sectors 35 and 36 and counts for
// both; one at 92° lies inside sector 54 ([90°, 95°]) alone.
TEST(SectorObstaclesTest, ScanRaysBecomeSectorDistancesAsFractionsOfTheRange) {
  std::vector<float> ranges(kRays, std::numeric_limits<float>::infinity());
  ranges[0] = 1.0f;  // 0°
  ranges[18] = 0.5f;  // 90°: the border of sectors 53 and 54
  LaserRays scan{0, 2 * M_PI / kRays, ranges};
  int invalid = -1;
  std::vector<double> sectors = sectorObstacles(scan, 2.0, &invalid);
  EXPECT_EQ(invalid, 0);
  EXPECT_DOUBLE_EQ(sectors[35], 0.5);
  EXPECT_DOUBLE_EQ(sectors[36], 0.5);
  EXPECT_DOUBLE_EQ(sectors[53], 0.25);
  EXPECT_DOUBLE_EQ(sectors[54], 0.25);
  EXPECT_DOUBLE_EQ(sectors[37], 1.0);  // +inf: nothing within range
  EXPECT_DOUBLE_EQ(sectors[0], 1.0);
  // Rays rotated by 2°: each lies inside one sector.
  scan.angle_min = 2 * M_PI / 180;
  sectors = sectorObstacles(scan, 2.0, &invalid);
  EXPECT_DOUBLE_EQ(sectors[36], 0.5);
  EXPECT_DOUBLE_EQ(sectors[35], 1.0);
  EXPECT_DOUBLE_EQ(sectors[54], 0.25);
  // A NaN ray is no reading: taken as an obstacle at the robot, and counted.
  scan.angle_min = 0;
  scan.ranges[36] = std::numeric_limits<float>::quiet_NaN();  // 180°: the border of sectors 71 and 0
  sectors = sectorObstacles(scan, 2.0, &invalid);
  EXPECT_EQ(invalid, 1);
  EXPECT_DOUBLE_EQ(sectors[0], 0.0);
  EXPECT_DOUBLE_EQ(sectors[71], 0.0);
  // Beyond the range a distance is 1.
  scan.ranges[0] = 7.0f;
  sectors = sectorObstacles(scan, 2.0, &invalid);
  EXPECT_DOUBLE_EQ(sectors[36], 1.0);
}

// A LaserScan's angle increment is a float, so its rays come out a little off the sector borders they lie on
// (up to 2e-6 sector widths for 72 rays). Each ray must still count for both sectors: every ray alone, at a
// distance of its own, gives the same sectors with the float increment as with the exact one.
TEST(SectorObstaclesTest, FloatScanAnglesGiveTheSectorsOfTheExactAngles) {
  for (int ray = 0; ray < kRays; ++ray) {
    std::vector<float> ranges(kRays, std::numeric_limits<float>::infinity());
    ranges[ray] = 1.0f;
    int invalid = 0;
    const std::vector<double> exact = sectorObstacles(LaserRays{0, 2 * M_PI / kRays, ranges}, 2.0, &invalid);
    const std::vector<double> rounded =
        sectorObstacles(LaserRays{0, static_cast<float>(2 * M_PI / kRays), ranges}, 2.0, &invalid);
    EXPECT_EQ(rounded, exact) << "ray " << ray;
    EXPECT_EQ(std::count(exact.begin(), exact.end(), 0.5), 2) << "ray " << ray << " is not on a border";
  }
}

// Cast on a known map: from the centre of cell (1, 1) of a 4x3 map of 1 m cells, east meets the wall at x = 3
// (1.5 m), west the map's edge (1.5 m), north the edge (1.5 m from y = 1.5 to 3... the top row is free).
TEST(SectorObstaclesTest, MapCastsEndAtKnownObstaclesAndTheMapsEdge) {
  const GridMap map = test::mapPicture({"....", ".S.#", "...."});
  const MapPoint robot = map.centre(Cell{1, 1});
  const std::vector<double> sectors = sectorObstaclesInMap(map, robot, 0.0, 3.0, 0.0);
  // Sector 36 is centred at 2.5°, so its ray meets x = 3 at 1.5 / cos 2.5° m; sector 71 (177.5°) meets x = 0
  // after 1.5 / cos 2.5° m; sector 54 (92.5°) meets y = 3 after 1.5 / cos 2.5° m.
  const double along = 1.5 / std::cos(2.5 * M_PI / 180) / 3.0;
  const double step = 1.0 / 8 / 3.0;  // the cast's resolution, as a fraction of the range
  EXPECT_NEAR(sectors[36], along, step);
  EXPECT_NEAR(sectors[71], along, step);
  EXPECT_NEAR(sectors[54], along, step);
}

// By hand: a disc of 0.2 m and one return 1 m away along sector 36's centre (2.5°). Sector 36 travels 1 - 0.2 m;
// sector 35, 5° off, meets it 0.0872 m to its side: cos 5° - sqrt(0.2² - sin² 5°) m. The disc touches it from
// every direction within asin(0.2) = 11.5° of it, sectors 34 to 38; a point only from sector 36.
TEST(SectorObstaclesTest, ADiscTravelsUntilItTouchesAReturn) {
  const double ray = sectorAngle(36);
  const LaserRays scan{ray, 2 * M_PI / 360, std::vector<float>(360, kNoReturn)};
  LaserRays one = scan;
  one.ranges[0] = 1.0f;
  int invalid = -1;
  const std::vector<double> disc = sectorObstaclesForDisc(one, 2.0, 0.2, &invalid);
  EXPECT_EQ(invalid, 0);
  EXPECT_NEAR(disc[36], 0.8 / 2, 1e-9);
  const double five = 5 * M_PI / 180;
  EXPECT_NEAR(disc[35], (std::cos(five) - std::sqrt(0.04 - std::sin(five) * std::sin(five))) / 2, 1e-9);
  EXPECT_LT(disc[38], 1.0);
  EXPECT_LT(disc[34], 1.0);
  EXPECT_EQ(std::count(disc.begin(), disc.end(), 1.0), kReactiveSectors - 5);
  const std::vector<double> point = sectorObstacles(one, 2.0, &invalid);
  EXPECT_EQ(std::count(point.begin(), point.end(), 1.0), kReactiveSectors - 1);
  EXPECT_NEAR(point[36], 0.5, 1e-7);
}

// A return inside the disc (0.1 m ahead of a disc of 0.2 m) stops every direction that goes deeper into it and
// none that leaves it, as MRPT's "back away" collision behaviour; a NaN ray stops its own sector, as for a point.
TEST(SectorObstaclesTest, AReturnInsideTheDiscStopsOnlyTheDirectionsIntoIt) {
  LaserRays scan{sectorAngle(36), 2 * M_PI / 360, std::vector<float>(360, kNoReturn)};
  scan.ranges[0] = 0.1f;
  int invalid = -1;
  std::vector<double> disc = sectorObstaclesForDisc(scan, 2.0, 0.2, &invalid);
  EXPECT_EQ(disc[36], 0.0);
  EXPECT_EQ(disc[0], 1.0);   // straight away from it
  EXPECT_EQ(disc[18], 1.0);  // sideways: it leaves the disc after 0.17 m
  scan.ranges[0] = kNoReturn;
  scan.ranges[180] = std::numeric_limits<float>::quiet_NaN();  // sectorAngle(36) + 180°: sector 0
  disc = sectorObstaclesForDisc(scan, 2.0, 0.2, &invalid);
  EXPECT_EQ(invalid, 1);
  EXPECT_EQ(disc[0], 0.0);
  EXPECT_EQ(std::count(disc.begin(), disc.end(), 1.0), kReactiveSectors - 1);
}

// The independent check: on 200 random scans of 360 rays for each of three radii (returns from 0.05 to 4 m, a
// tenth of them none, some inside the disc), the disc's travel per sector is what MRPT's own trajectories for a
// round robot at rest give, within 1e-5 of the range: MRPT finds each contact as the root of a quartic
// (solve_poly4), and near a grazing contact its roots are off by up to 6e-6 of the range here (24 of the 43,200
// values by more than 1e-6).
TEST(SectorObstaclesTest, DiscTravelIsMrptsStraightTrajectoriesForARoundRobot) {
  const double range = 3.5;
  std::mt19937 random(1);
  std::uniform_real_distribution<double> distance(0.05, 4.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const double radius : {0.05, 0.2, 0.45}) {
    const mrpt::nav::CPTG_Holo_Blend ptg = test::holoBlend(radius, range);
    for (int trial = 0; trial < 200; ++trial) {
      LaserRays scan{-M_PI + unit(random), 2 * M_PI / 360, std::vector<float>(360)};
      for (float& r : scan.ranges) r = unit(random) < 0.1 ? kNoReturn : static_cast<float>(distance(random));
      int invalid = 0;
      const std::vector<double> ours = sectorObstaclesForDisc(scan, range, radius, &invalid);
      const std::vector<double> mrpts = test::holoBlendObstacles(ptg, scan, range);
      for (int k = 0; k < kReactiveSectors; ++k) {
        ASSERT_NEAR(ours[k], mrpts[k], 1e-5) << "radius " << radius << ", scan " << trial << ", sector " << k;
      }
    }
  }
}

// Cast for a disc of 0.3 m on a 5x4 map of 1 m cells from the centre of cell (2, 1), (2.5, 2.5) m: the wall cell
// (4, 1) begins at x = 4 and the map's top edge is y = 4, each 1.2 m of travel away for the disc; its left and bottom
// edges 2.2 m. Sector 54 (92.5° in the robot's frame) is north when the robot heads east and west when it heads
// north.
TEST(SectorObstaclesTest, MapCastsForADiscStopWhereItTouchesAndTurnWithTheHeading) {
  const GridMap map = test::mapPicture({".....", "..S.#", ".....", "....."});
  const MapPoint robot = map.centre(Cell{2, 1});
  const double step = 1.0 / 8 / 3.0;  // the cast's resolution, as a fraction of the range
  const double slant = std::cos(2.5 * M_PI / 180);
  std::vector<double> sectors = sectorObstaclesInMap(map, robot, 0.0, 3.0, 0.3);
  EXPECT_NEAR(sectors[36], 1.2 / slant / 3.0, step);  // east, to the wall cell
  EXPECT_NEAR(sectors[54], 1.2 / slant / 3.0, step);  // north, to the top edge
  EXPECT_NEAR(sectors[0], 2.2 / slant / 3.0, step);   // west, to the left edge
  sectors = sectorObstaclesInMap(map, robot, M_PI / 2, 3.0, 0.3);
  EXPECT_NEAR(sectors[54], 2.2 / slant / 3.0, step);  // now west
  EXPECT_NEAR(sectors[18], 1.2 / slant / 3.0, step);  // now east
  EXPECT_NEAR(sectors[0], 2.2 / slant / 3.0, step);   // now south
}

}  // namespace
}  // namespace planners
}  // namespace ppp
