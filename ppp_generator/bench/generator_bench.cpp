// Speed of the genetic algorithm: full runs of mating events, per fitness and per map size.
#include <benchmark/benchmark.h>

#include "ppp_generator/genetic_algorithm.hpp"

namespace {

/// The names benchmarked, indexed by the first argument.
const char* const kFitness[] = {"turns", "difficulty", "random"};

/// One complete run: initial pool of 60 plus `matings` mating events on a side x side grid, with crowding
/// replacement (the default; fourth argument 0) or the dissertation's tournament replacement (1).
void BM_Generate(benchmark::State& state) {
  ppp::generator::GeneratorOptions options;
  options.fitness = kFitness[state.range(0)];
  options.width = options.height = static_cast<int>(state.range(1));
  options.matings = state.range(2);
  options.replacement =
      state.range(3) == 0 ? ppp::generator::kCrowdingReplacement : ppp::generator::kTournamentReplacement;
  options.population = 60;
  options.seed = 1;
  for (auto _ : state) {
    ppp::generator::GeneticAlgorithm ga(options);
    benchmark::DoNotOptimize(ga.run());
  }
  state.SetLabel(options.fitness + " " + std::to_string(options.width) + "x" + std::to_string(options.height) + " " +
                 options.replacement);
  state.counters["matings/s"] = benchmark::Counter(static_cast<double>(options.matings) * state.iterations(),
                                                   benchmark::Counter::kIsRate);
}

// The target: 10,000 matings, population 60, 20x20, <= 1 s for turns and for difficulty.
BENCHMARK(BM_Generate)
    ->Args({0, 20, 10000, 0})
    ->Args({1, 20, 10000, 0})
    ->Args({2, 20, 10000, 0})
    ->Args({0, 20, 10000, 1})
    ->Args({1, 20, 10000, 1})
    ->Unit(benchmark::kMillisecond);
// Growth with map size (1,000 matings each; the default budget of 10 obstacles).
BENCHMARK(BM_Generate)
    ->Args({0, 50, 1000, 0})
    ->Args({0, 100, 1000, 0})
    ->Args({0, 200, 1000, 0})
    ->Args({1, 50, 1000, 0})
    ->Args({1, 100, 1000, 0})
    ->Args({1, 200, 1000, 0})
    ->Unit(benchmark::kMillisecond);

}  // namespace
