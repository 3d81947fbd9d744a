// DpaSolver::solve on the benchmark maps, one solver reused across iterations.

#include <benchmark/benchmark.h>

#include "bench_maps.hpp"
#include "ppp_core/dpa.hpp"

namespace ppp::bench {
namespace {

void BM_DpaFullSolve(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  const Problem& problem = benchProblem(side);
  const Grid& grid = benchGrid(side);
  DpaSolver solver;
  if (!solver.solve(grid, problem.start, problem.goal).reachable) {
    state.SkipWithError("benchmark map is not solvable");
    return;
  }
  for (auto _ : state) {
    const DpaResult& result = solver.solve(grid, problem.start, problem.goal);
    benchmark::DoNotOptimize(result.turns_plus_advances);
    benchmark::ClobberMemory();
  }
  const DpaResult& result = solver.solve(grid, problem.start, problem.goal);
  state.counters["turns"] = result.turns;
  state.counters["advances"] = result.advances;
  state.SetLabel(describe(side));
}
BENCHMARK(BM_DpaFullSolve)->Arg(20)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DpaFullSolve)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ppp::bench
