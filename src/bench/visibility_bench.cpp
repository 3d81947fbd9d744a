// Visibility from the centre cell: the cone sweep (VisibilitySolver) against lineOfSight to every cell.

#include <benchmark/benchmark.h>

#include "bench_maps.hpp"
#include "ppp_core/visibility.hpp"

namespace ppp::bench {
namespace {

/// Cells visible from `viewpoint`, by testing lineOfSight to every cell of the grid.
int naiveVisibleCount(const Grid& grid, Cell viewpoint) {
  int count = 0;
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) count += lineOfSight(grid, viewpoint, Cell{x, y}) ? 1 : 0;
  }
  return count;
}

void BM_VisibilityOneViewpoint(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  const Grid& grid = benchGrid(side);
  const Cell viewpoint = centreCell(benchProblem(side));
  VisibilitySolver solver;
  int visible = 0;
  for (auto _ : state) {
    visible = solver.solve(grid, viewpoint);
    benchmark::DoNotOptimize(visible);
    benchmark::ClobberMemory();
  }
  state.counters["visible"] = visible;
  state.SetLabel(describe(side));
}
BENCHMARK(BM_VisibilityOneViewpoint)->Arg(20)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_VisibilityOneViewpoint)->Arg(200)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_VisibilityOneViewpoint)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_VisibilityNaive(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  const Grid& grid = benchGrid(side);
  const Cell viewpoint = centreCell(benchProblem(side));
  VisibilitySolver solver;
  if (naiveVisibleCount(grid, viewpoint) != solver.solve(grid, viewpoint)) {
    state.SkipWithError("lineOfSight and VisibilitySolver disagree");
    return;
  }
  int visible = 0;
  for (auto _ : state) {
    visible = naiveVisibleCount(grid, viewpoint);
    benchmark::DoNotOptimize(visible);
  }
  state.counters["visible"] = visible;
  state.SetLabel(describe(side));
}
BENCHMARK(BM_VisibilityNaive)->Arg(20)->Unit(benchmark::kMicrosecond);
// 1000x1000 would take minutes per repetition (about side^3 work); 200x200 already shows the gap.
BENCHMARK(BM_VisibilityNaive)->Arg(200)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ppp::bench
