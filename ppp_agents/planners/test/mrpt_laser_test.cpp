// The continuous model's exact laser against MRPT's laserScanSimulator on the same maps and beams: the ranges
// agree to within MRPT's grid resolution, except where MRPT, marching its rays a cell at a time, steps over the
// corner of a square that a ray only clips: there MRPT reads farther, never nearer.

#include "mrpt_laser.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ppp_core/random_problem.hpp"
#include "ppp_core/square_world.hpp"

namespace ppp {
namespace planners {
namespace {

TEST(MrptLaserTest, RangesAgreeWithMrptsSimulatorWithinItsResolution) {
  Rng rng(4);
  MotionOptions options;
  const LaserBeams beams = LaserBeams::of(options);
  int compared = 0, agreed = 0;
  for (int map_index = 0; map_index < 5; ++map_index) {
    const Problem problem = randomProblem(rng, Problem::empty(20, 20, 10), 10);
    const Grid grid = decodeGrid(problem);
    const SquareWorld world(grid, options.resolution);
    const mrpt::maps::COccupancyGridMap2D map = mrptLaserMap(grid, options.resolution);
    for (int pose_index = 0; pose_index < 10; ++pose_index) {
      const Pose2D pose{rng.uniform01() * world.widthMetres(), rng.uniform01() * world.heightMetres(),
                        rng.uniform01() * 6.28 - 3.14};
      if (world.clearance(pose.x, pose.y, 1) < 0.1) continue;  // a robot stands clear of the walls
      std::vector<float> ours, theirs;
      scanLaser(world, pose, beams, nullptr, &ours);
      mrptScan(map, pose, beams, &theirs);
      for (int i = 0; i < beams.count; ++i) {
        const double limit = options.laser_range - options.resolution;  // near the range, one may see and one not
        if (!(ours[i] < limit) || !(theirs[i] < limit)) continue;
        ++compared;
        if (std::fabs(ours[i] - theirs[i]) <= options.resolution) {
          ++agreed;
        } else {
          EXPECT_GT(theirs[i], ours[i]) << "map " << map_index << " pose " << pose_index << " beam " << i;
        }
      }
    }
  }
  EXPECT_GT(compared, 3000);
  EXPECT_GE(agreed, 0.99 * compared);
}

}  // namespace
}  // namespace planners
}  // namespace ppp
