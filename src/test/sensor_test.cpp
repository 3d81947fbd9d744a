#include "ppp_core/sensor.hpp"

#include <gtest/gtest.h>

#include "grid_picture.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/visibility.hpp"

namespace ppp {
namespace {

using test::picture;

std::vector<std::string> drawScan(const Scan& scan) {
  std::vector<std::string> rows;
  for (int dy = -scan.range(); dy <= scan.range(); ++dy) {
    std::string row;
    for (int dx = -scan.range(); dx <= scan.range(); ++dx) {
      const auto v = scan.at(dx, dy);
      row += v == kScanFree ? '.' : v == kScanObstacle ? '#' : v == kScanOutOfBounds ? 'x' : '?';
    }
    rows.push_back(row);
  }
  return rows;
}

TEST(SensorTest, WindowWorkedByHand) {
  // Robot at (1,1) next to a wall at (2,0..2): the wall is seen, the cells behind it are not, and that
  // includes (3,3) and (4,3), whose segments cross (2,2), and the edge cells beyond the wall: an occluded
  // cell is unknown even when it lies off the map (the sensor cannot see the edge there).
  auto p = picture({
      "..#..",
      ".S#..",
      "..#..",
      ".....",
  });
  SensorModel sensor(SensorOptions{2, 0.0});
  const Scan scan(sensor, p.grid, p.start, Cell{4, 3}, false, 0, 1);
  EXPECT_EQ(drawScan(scan), (std::vector<std::string>{
                                "xxx??",
                                "x..#?",
                                "x..#?",
                                "x..#?",
                                "x..??",
                            }));
}

TEST(SensorTest, AgreesWithLineOfSightOnRandomGrids) {
  // Range 3 (49 cells) takes the bit-mask path, range 5 (121 cells) the list path.
  for (int range : {3, 5}) {
    Rng rng(3);
    SensorModel sensor(SensorOptions{range, 0.0});
    for (int trial = 0; trial < 200; ++trial) {
      Grid g(9, 8);
      for (int i = 0; i < g.size(); ++i) g.setObstacle(g.cellAt(i), rng.bernoulli(0.3));
      const Cell at{static_cast<int>(rng.below(9)), static_cast<int>(rng.below(8))};
      const Scan scan(sensor, g, at, Cell{0, 0}, false, 0, 1);
      for (int dy = -range; dy <= range; ++dy) {
        for (int dx = -range; dx <= range; ++dx) {
          const Cell c{at.x + dx, at.y + dy};
          const std::int8_t expected = !lineOfSight(g, at, c) ? kScanUnknown
                                       : !g.contains(c)        ? kScanOutOfBounds
                                       : g.isObstacle(c)       ? kScanObstacle
                                                               : kScanFree;
          ASSERT_EQ(scan.at(dx, dy), expected) << "range " << range << " trial " << trial << " " << dx << "," << dy;
        }
      }
    }
  }
}

TEST(SensorTest, NoiseFlipsSensedCellsAtItsRate) {
  Grid g(30, 30);
  SensorModel sensor(SensorOptions{2, 0.1});
  long sensed = 0, flipped = 0;
  for (int step = 0; step < 20000; ++step) {
    const Scan scan(sensor, g, Cell{15, 15}, Cell{0, 0}, false, step, 77);
    EXPECT_EQ(scan.at(0, 0), kScanFree) << "the robot's own cell is never flipped";
    for (int i = 0; i < 25; ++i) {
      if (i == 12) continue;
      ++sensed;
      flipped += scan.cells()[i] == kScanObstacle ? 1 : 0;
    }
  }
  // Binomial(480000, 0.1): standard deviation 208; allow 4 of them.
  EXPECT_NEAR(flipped, 0.1 * sensed, 4 * 208);
}

TEST(SensorTest, NoiseNeverTouchesUnknownOrOutOfBoundsAndIsReproducible) {
  auto p = picture({"S#..", "....", "...."});
  SensorModel sensor(SensorOptions{2, 1.0});
  const Scan a(sensor, p.grid, p.start, Cell{3, 2}, false, 5, 9);
  EXPECT_EQ(a.at(-1, 0), kScanOutOfBounds);
  EXPECT_EQ(a.at(2, 0), kScanUnknown);  // behind the obstacle at (1,0)
  EXPECT_EQ(a.at(1, 0), kScanFree);     // the obstacle, reported flipped
  const std::vector<std::int8_t> cells(a.cells(), a.cells() + 25);
  const Scan b(2, cells, p.start, Cell{3, 2}, false, 5);
  for (int dy = -2; dy <= 2; ++dy) {
    for (int dx = -2; dx <= 2; ++dx) EXPECT_EQ(a.at(dx, dy), b.at(dx, dy));
  }
  EXPECT_EQ(b.atCell(Cell{3, 2}), kScanUnknown);  // outside the window
}

TEST(SensorTest, NoiseFlipsAsAMaskAreTheCellsAddNoiseFlips) {
  // Every cell free except the centre's row of obstacles: addNoise flips a cell exactly where the mask says.
  for (int range = 1; range <= 3; ++range) {
    const SensorModel sensor(SensorOptions{range, 0.4});
    const int cells = (2 * range + 1) * (2 * range + 1);
    for (int step = 0; step < 50; ++step) {
      std::vector<std::int8_t> window(cells, kScanFree);
      sensor.addNoise(77, step, window.data());
      const std::uint64_t flips = sensor.noiseFlips(77, step);
      for (int i = 0; i < cells; ++i) {
        ASSERT_EQ(window[i] == kScanObstacle, (flips >> i & 1) != 0) << "range " << range << " step " << step;
      }
      EXPECT_EQ(flips >> (range * (2 * range + 1) + range) & 1, 0u);  // never the robot's own cell
    }
  }
  EXPECT_EQ(SensorModel(SensorOptions{4, 0.0}).noiseFlips(1, 1), 0u);  // no noise: nothing to flip, any range
  try {
    SensorModel(SensorOptions{4, 0.1}).noiseFlips(1, 1);  // 81 cells do not fit a mask
    FAIL() << "a mask of 81 cells";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "sensor_range");
  }
}

TEST(SensorTest, BadOptions) {
  EXPECT_THROW(SensorModel(SensorOptions{0, 0.0}), InvalidArgument);
  EXPECT_THROW(SensorModel(SensorOptions{8, 0.0}), InvalidArgument);
  EXPECT_THROW(SensorModel(SensorOptions{2, 1.5}), InvalidArgument);
  EXPECT_THROW(SensorModel(SensorOptions{2, -0.1}), InvalidArgument);
  EXPECT_THROW(Scan(2, std::vector<std::int8_t>(24, 0), Cell{}, Cell{}, false, 0), InvalidArgument);
}

}  // namespace
}  // namespace ppp
