// What a large map costs: the step cost of every agent configuration of the default experiment and the mating
// cost of the generator (turns, difficulty and the failure fitness of the default hunt) at map sides 20, 100, 512
// and 1000, on PPPs of the generator's own kind (10 obstacle descriptors, bars up to half a side, blocks up to a
// quarter). scripts/bench-scale.sh runs it beside the peak memory of an experiment at each side.
//   scale_bench [--benchmark_filter=Step]

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <string>

#include "ppp_core/random_problem.hpp"
#include "ppp_core/reachability.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/window_atlas.hpp"
#include "ppp_generator/genetic_algorithm.hpp"
#include "ppp_agents/episode_runner.hpp"
#include "ppp_generator/failure_fitness.hpp"
#include "default_agents.hpp"

namespace {

/// A random solvable side x side PPP of the generator's kind.
ppp::Problem scaledProblem(int side) {
  ppp::Rng rng(static_cast<std::uint64_t>(side));
  for (;;) {
    ppp::Problem p = ppp::Problem::empty(side, side, 10);
    p.goal = ppp::Cell{side - 1, side - 1};
    for (int i = 0; i < 10; ++i) p.obstacles.push_back(ppp::randomObstacle(rng, side, side, {}));
    if (ppp::isReachable(ppp::decodeGrid(p), p.start, p.goal)) return p;
  }
}

/// Whole episodes (budget 300) of one agent configuration, with the window atlas where the engine keeps one
/// (maps up to kMaxWindowAtlasBytes of windows); the reported time is per agent-step.
void BM_Step(benchmark::State& state) {
  const ppp::agents::AgentConfig config = ppp::bench::defaultAgent(static_cast<int>(state.range(0)));
  const int side = static_cast<int>(state.range(1));
  const ppp::Problem problem = scaledProblem(side);
  const ppp::Grid grid = ppp::decodeGrid(problem);
  const int range = ppp::EpisodeOptions{}.sensor_range;
  std::optional<ppp::WindowAtlas> windows;
  if (ppp::WindowAtlas::bytes(grid, range) <= ppp::kMaxWindowAtlasBytes) windows.emplace(grid, range);
  ppp::agents::EpisodeRunner runner(config, ppp::EpisodeOptions{});
  auto agent = ppp::agents::makeAgent(config);
  std::uint64_t run = 0;
  std::int64_t steps = 0;
  for (auto _ : state) {
    steps += runner.run(problem, grid, *agent, ++run, false, windows ? &*windows : nullptr).steps;
  }
  state.SetLabel(config.name + " " + std::to_string(side) + "x" + std::to_string(side));
  state.counters["ns/step"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate |
                                                                                benchmark::Counter::kInvert);
  state.counters["steps/s"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Step)
    ->ArgsProduct({{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}, {20, 100, 512, 1000}})
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(0.2);

/// The fitness benchmarked by BM_Mating, indexed by its first argument.
const char* const kFitness[] = {"turns", "difficulty", "failure"};

/// Time per mating event at one map side: a run with `matings` mating events less the same run (same seed,
/// so the same initial pool) with none, divided by `matings`. Population 20 (the initial pool of large maps
/// is what a run with few matings mostly costs), one worker thread for the failure fitness.
void BM_Mating(benchmark::State& state) {
  const std::string fitness = kFitness[state.range(0)];
  const int side = static_cast<int>(state.range(1));
  const int matings = static_cast<int>(state.range(2));
  ppp::generator::GeneratorOptions options;
  options.fitness = fitness;
  options.width = options.height = side;
  options.population = 20;
  options.seed = 1;
  if (fitness == "failure") {
    options.agents = {"wall_follower_left", "explorer", "bumper"};
    options.crowding_window = 4;
  }
  const auto timed_run = [&](int count) {
    options.matings = count;
    ppp::generator::GeneticAlgorithm ga(options, ppp::generator::fitnessFor(options, {}, ppp::EpisodeOptions{}, 1));
    const auto start = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(ga.run());
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  for (auto _ : state) {
    const double pool = timed_run(0);
    const double all = timed_run(matings);
    state.SetIterationTime(std::max(all - pool, 0.0) / matings);
  }
  state.SetLabel(fitness + " " + std::to_string(side) + "x" + std::to_string(side) + ", per mating");
}
BENCHMARK(BM_Mating)
    ->ArgsProduct({{0, 1, 2}, {20}, {400}})
    ->ArgsProduct({{0, 1, 2}, {100}, {100}})
    ->ArgsProduct({{0, 1, 2}, {512}, {20}})
    ->ArgsProduct({{0, 1, 2}, {1000}, {10}})
    ->UseManualTime()
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
