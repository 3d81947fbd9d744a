// The robot's laser-built map in continuous motion: a scan worked out by hand, and, on random maps seen from
// every free cell centre (where beams meet corners) and from random poses, no cell marked other than it is.

#include "ppp_agents/continuous/laser_memory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ppp_core/random_problem.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/sensor.hpp"
#include "ppp_core/square_world.hpp"

namespace ppp {
namespace agents {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(LaserMemoryTest, FourBeamsMarkTheCellsTheyCrossAndTheSquareTheyMeet) {
  // 5x5 cells of 1 m, one obstacle at grid (3, 2); the robot at grid (1, 2)'s centre, (1.5, 2.5) in the map frame.
  Grid grid(5, 5);
  grid.setObstacle(Cell{3, 2}, true);
  const SquareWorld world(grid, 1.0);
  const LaserBeams beams = LaserBeams::fan(4, -kPi, kPi / 2, 10, 0);  // west, south, east, north
  const Pose2D pose{1.5, 2.5, 0};
  std::vector<float> ranges;
  scanLaser(world, pose, beams, nullptr, &ranges);
  ASSERT_EQ(ranges.size(), 4u);
  EXPECT_NEAR(ranges[0], 1.5, 1e-6);  // the border at x = 0
  EXPECT_NEAR(ranges[2], 1.5, 1e-6);  // the square's face at x = 3
  LaserMemory memory;
  memory.start(world.frame(), pose);
  EXPECT_TRUE(memory.add(pose, ranges, beams));
  // Grid y = 4 - map row. Free: row 2 from column 0 to 2 and column 1 from top to bottom; the obstacle at (3, 2).
  std::vector<std::string> expected = {".f...", ".f...", "fffx.", ".f...", ".f..."};
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 5; ++x) {
      const std::int8_t v = memory.cells()[static_cast<std::size_t>(y * 5 + x)];
      const char got = v == kScanFree ? 'f' : v == kScanObstacle ? 'x' : '.';
      EXPECT_EQ(got, expected[y][x]) << "grid (" << x << ", " << y << ")";
    }
  }
  EXPECT_FALSE(memory.add(pose, ranges, beams));  // nothing new the second time
}

/// Checks every known cell of `memory` against `grid`; returns how many are known.
int checkAgainstTruth(const LaserMemory& memory, const Grid& grid, const std::string& where) {
  int known = 0;
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      const std::int8_t v = memory.cells()[static_cast<std::size_t>(grid.index(Cell{x, y}))];
      if (v == kScanUnknown) continue;
      ++known;
      EXPECT_EQ(v == kScanObstacle, grid.isObstacle(Cell{x, y})) << where << ", grid (" << x << ", " << y << ")";
    }
  }
  return known;
}

TEST(LaserMemoryTest, MarksNoCellOtherThanItIsFromCellCentresAndRandomPoses) {
  Rng rng(21);
  MotionOptions options;
  const LaserBeams beams = LaserBeams::of(options);  // 360 beams a degree apart: from a centre some meet corners
  std::vector<float> ranges;
  long known = 0, corner_views = 0;
  for (int map = 0; map < 12; ++map) {
    const Problem problem = randomProblem(rng, Problem::empty(12, 12, 10), 10);
    const Grid grid = decodeGrid(problem);
    const SquareWorld world(grid, 0.5);
    for (int y = 0; y < 12; ++y) {
      for (int x = 0; x < 12; ++x) {
        if (!grid.isFree(Cell{x, y})) continue;
        const Cell c{x, y};
        const double jitter_x = (map % 2 == 0) ? 0.5 : rng.uniform01();  // even maps: exact centres
        const double jitter_y = (map % 2 == 0) ? 0.5 : rng.uniform01();
        const Pose2D pose{(x + jitter_x) * 0.5, (world.frame().mapRow(c) + jitter_y) * 0.5,
                          (map % 3) * kPi / 4 + rng.uniform01() * (map % 2)};
        scanLaser(world, pose, beams, nullptr, &ranges);
        LaserMemory memory;
        memory.start(world.frame(), pose);
        memory.add(pose, ranges, beams);
        known += checkAgainstTruth(memory, grid, "map " + std::to_string(map) + " from grid (" +
                                                     std::to_string(x) + ", " + std::to_string(y) + ")");
        corner_views += map % 2 == 0;
      }
    }
  }
  EXPECT_GT(corner_views, 300);
  EXPECT_GT(known, 20000);  // the scans do see: not vacuous
}

TEST(LaserMemoryTest, AnObstacleStaysOneAndBeamsOffTheMapMarkNothing) {
  Grid grid(3, 2);  // the obstacle in map row 1, the top one
  grid.setObstacle(Cell{2, 0}, true);
  const SquareWorld world(grid, 1.0);
  const LaserBeams beams = LaserBeams::fan(1, 0, 0, 10, 0);  // east
  LaserMemory memory;
  const Pose2D pose{0.5, 1.5, 0};
  memory.start(world.frame(), pose);
  EXPECT_TRUE(memory.add(pose, {1.5f}, beams));
  EXPECT_EQ(memory.at(2, 1), kScanObstacle);
  EXPECT_EQ(memory.at(1, 1), kScanFree);
  // A (noisy) longer reading crosses the square: it stays an obstacle.
  memory.add(pose, {2.2f}, beams);
  EXPECT_EQ(memory.at(2, 1), kScanObstacle);
  // West, no return within range: the beam leaves the map at once, through the start cell known already.
  LaserMemory open;
  open.start(world.frame(), pose);
  EXPECT_FALSE(open.add(pose, {std::numeric_limits<float>::infinity()}, LaserBeams::fan(1, kPi, 0, 10, 0)));
  EXPECT_EQ(open.at(0, 1), kScanFree);
  EXPECT_EQ(open.at(1, 1), kScanUnknown);
  EXPECT_EQ(open.at(0, 0), kScanUnknown);
}

}  // namespace
}  // namespace agents
}  // namespace ppp
