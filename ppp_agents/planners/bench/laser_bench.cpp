// A laser scan of the continuous model (exact casts against the cell squares) against MRPT's laserScanSimulator
// (rays marched over its occupancy grid) on the same 20x20 PPP, beams and poses: 360 beams over 360 degrees,
// 3.5 m range, 1 m cells. Then what a holonomic method is given from such a scan: the nearest ray per sector (a
// point), the disc's travel per sector (a body of 0.2 m), and the same travel from MRPT's own straight trajectories
// for a round robot (CPTG_Holo_Blend::updateTPObstacle, what its navigator computes).
//   laser_bench [--benchmark_repetitions=3]

#include <benchmark/benchmark.h>

#include <vector>

#include "../mrpt_laser.hpp"
#include "../sector_obstacles.hpp"
#include "../test/holo_blend.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/square_world.hpp"

namespace {

struct Scene {
  ppp::Grid grid;
  std::vector<ppp::Pose2D> poses;
  ppp::LaserBeams beams = ppp::LaserBeams::of(ppp::MotionOptions{});
};

const Scene& scene() {
  static const Scene s = [] {
    Scene made;
    ppp::Rng rng(20);
    made.grid = ppp::decodeGrid(ppp::randomProblem(rng, ppp::Problem::empty(20, 20, 10), 10));
    const ppp::SquareWorld world(made.grid, 1.0);
    while (made.poses.size() < 64) {
      const ppp::Pose2D pose{rng.uniform01() * 20, rng.uniform01() * 20, rng.uniform01() * 6.28 - 3.14};
      if (world.clearance(pose.x, pose.y, 1) > 0.2) made.poses.push_back(pose);
    }
    return made;
  }();
  return s;
}

void exactScan(benchmark::State& state) {
  const Scene& s = scene();
  const ppp::SquareWorld world(s.grid, 1.0);
  std::vector<float> ranges;
  std::size_t i = 0;
  for (auto _ : state) {
    ppp::scanLaser(world, s.poses[i++ % s.poses.size()], s.beams, nullptr, &ranges);
    benchmark::DoNotOptimize(ranges.data());
  }
  state.SetItemsProcessed(state.iterations());
}

void mrptScan(benchmark::State& state) {
  const Scene& s = scene();
  const mrpt::maps::COccupancyGridMap2D map = ppp::planners::mrptLaserMap(s.grid, 1.0);
  std::vector<float> ranges;
  std::size_t i = 0;
  for (auto _ : state) {
    ppp::planners::mrptScan(map, s.poses[i++ % s.poses.size()], s.beams, &ranges);
    benchmark::DoNotOptimize(ranges.data());
  }
  state.SetItemsProcessed(state.iterations());
}

/// The scans at every pose of the scene, as a LaserScan gives them.
const std::vector<ppp::planners::LaserRays>& sceneScans() {
  static const std::vector<ppp::planners::LaserRays> scans = [] {
    const Scene& s = scene();
    const ppp::SquareWorld world(s.grid, 1.0);
    std::vector<ppp::planners::LaserRays> made;
    for (const ppp::Pose2D& pose : s.poses) {
      made.push_back({s.beams.angle_min, s.beams.angle_increment, {}});
      ppp::scanLaser(world, pose, s.beams, nullptr, &made.back().ranges);
    }
    return made;
  }();
  return scans;
}

void pointSectors(benchmark::State& state) {
  std::size_t i = 0;
  int invalid = 0;
  for (auto _ : state) {
    const auto sectors = ppp::planners::sectorObstacles(sceneScans()[i++ % sceneScans().size()], 3.5, &invalid);
    benchmark::DoNotOptimize(sectors.data());
  }
  state.SetItemsProcessed(state.iterations());
}

void discSectors(benchmark::State& state) {
  std::size_t i = 0;
  int invalid = 0;
  for (auto _ : state) {
    const auto sectors =
        ppp::planners::sectorObstaclesForDisc(sceneScans()[i++ % sceneScans().size()], 3.5, 0.2, &invalid);
    benchmark::DoNotOptimize(sectors.data());
  }
  state.SetItemsProcessed(state.iterations());
}

void mrptHoloBlendSectors(benchmark::State& state) {
  const mrpt::nav::CPTG_Holo_Blend ptg = ppp::planners::test::holoBlend(0.2, 3.5);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto sectors = ppp::planners::test::holoBlendObstacles(ptg, sceneScans()[i++ % sceneScans().size()], 3.5);
    benchmark::DoNotOptimize(sectors.data());
  }
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

BENCHMARK(exactScan);
BENCHMARK(mrptScan);
BENCHMARK(pointSectors);
BENCHMARK(discSectors);
BENCHMARK(mrptHoloBlendSectors);
