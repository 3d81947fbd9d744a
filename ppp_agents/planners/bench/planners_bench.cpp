// Plan times of the example planners on a 20x20 map with two long walls, corner to corner.
#include <benchmark/benchmark.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "ompl_grid_planner.hpp"
#include "optimistic_astar.hpp"
#include "ppp_core/map_frame.hpp"

namespace ppp {
namespace planners {
namespace {

constexpr int kSide = 20;

GridMap wallsMap() {
  const MapFrame frame{kSide, kSide, 1.0};
  std::vector<std::int8_t> data(kSide * kSide, 0);
  for (int y = 0; y < 16; ++y) data[static_cast<std::size_t>(frame.mapIndex(Cell{6, y}))] = 100;
  for (int y = 4; y < kSide; ++y) data[static_cast<std::size_t>(frame.mapIndex(Cell{13, y}))] = 100;
  return GridMap(kSide, kSide, 1.0, data, true);
}

void BM_OptimisticAStar(benchmark::State& state) {
  const GridMap map = wallsMap();
  for (auto _ : state) benchmark::DoNotOptimize(optimisticAStar(map, Cell{0, 0}, Cell{kSide - 1, kSide - 1}));
}
BENCHMARK(BM_OptimisticAStar);

/// OMPL's random numbers are process-global: seed them once, before the first plan.
const bool kOmplSeeded = [] {
  ompl::RNG::setSeed(1);
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  return true;
}();

void BM_OmplRRTConnect(benchmark::State& state) {
  const GridMap map = wallsMap();
  const OmplGridPlanner planner{OmplPlannerOptions{}};
  for (auto _ : state) {
    const std::vector<MapPoint> waypoints = planner.plan(map, Cell{0, 0}, Cell{kSide - 1, kSide - 1});
    if (waypoints.empty()) state.SkipWithError("no path");
    benchmark::DoNotOptimize(waypoints);
  }
}
BENCHMARK(BM_OmplRRTConnect)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace planners
}  // namespace ppp
