// Evaluator::evaluate (DPA, five visibilities, openness, difficulty) on the benchmark maps.

#include <benchmark/benchmark.h>

#include "bench_maps.hpp"
#include "ppp_core/evaluation.hpp"

namespace ppp::bench {
namespace {

void BM_FullEvaluation(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  const Problem& problem = benchProblem(side);
  const Grid& grid = benchGrid(side);
  Evaluator evaluator;
  for (auto _ : state) {
    Evaluation evaluation = evaluator.evaluate(problem, grid);
    benchmark::DoNotOptimize(evaluation);
  }
  state.counters["difficulty"] = evaluator.evaluate(problem, grid).difficulty;
  state.SetLabel(describe(side));
}
BENCHMARK(BM_FullEvaluation)->Arg(20)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FullEvaluation)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_FullEvaluationWithDecode(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  const Problem& problem = benchProblem(side);
  Evaluator evaluator;
  for (auto _ : state) {
    Evaluation evaluation = evaluator.evaluate(problem);
    benchmark::DoNotOptimize(evaluation);
  }
  state.SetLabel(describe(side));
}
BENCHMARK(BM_FullEvaluationWithDecode)->Arg(20)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FullEvaluationWithDecode)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ppp::bench
