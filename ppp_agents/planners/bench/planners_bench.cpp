// Plan times of the example planners on a 20x20 map with two long walls, corner to corner (and OMPL's when the
// goal is walled off).
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

/// The goal cell walled off by the three cells around it.
GridMap walledOffMap() {
  const MapFrame frame{kSide, kSide, 1.0};
  std::vector<std::int8_t> data(kSide * kSide, 0);
  for (const Cell wall : {Cell{kSide - 2, kSide - 1}, Cell{kSide - 2, kSide - 2}, Cell{kSide - 1, kSide - 2}}) {
    data[static_cast<std::size_t>(frame.mapIndex(wall))] = 100;
  }
  return GridMap(kSide, kSide, 1.0, data, true);
}

/// Plans corner to corner on `map` with the OMPL planner the benchmark's range names (0: RRTConnect, 1: RRTstar,
/// 2: PRM) at the default limits; an error unless a path is found exactly when `solvable`.
void planCornerToCorner(benchmark::State& state, const GridMap& map, bool solvable) {
  OmplPlannerOptions options;
  options.planner = omplPlannerNames()[static_cast<std::size_t>(state.range(0))];
  state.SetLabel(options.planner);
  const OmplGridPlanner planner{options};
  for (auto _ : state) {
    const std::vector<MapPoint> waypoints = planner.plan(map, Cell{0, 0}, Cell{kSide - 1, kSide - 1});
    if (waypoints.empty() == solvable) state.SkipWithError(solvable ? "no path" : "a path through a wall");
    benchmark::DoNotOptimize(waypoints);
  }
}

/// Each OMPL planner on the two walls: RRTConnect stops at its first path, RRTstar improves its path for all its
/// iterations.
void BM_OmplPlanner(benchmark::State& state) { planCornerToCorner(state, wallsMap(), true); }
BENCHMARK(BM_OmplPlanner)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

/// Each OMPL planner asked for a goal walled off from the start: it runs to its default iteration limit.
void BM_OmplPlannerUnreachable(benchmark::State& state) { planCornerToCorner(state, walledOffMap(), false); }
BENCHMARK(BM_OmplPlannerUnreachable)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace planners
}  // namespace ppp
