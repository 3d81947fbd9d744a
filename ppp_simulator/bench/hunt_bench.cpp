// Speed of fault hunting in process: the failure fitness's batch scoring and whole hunts.
#include <benchmark/benchmark.h>

#include <vector>

#include "ppp_core/random_problem.hpp"
#include "ppp_core/reachability.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_generator/set_evolution.hpp"
#include "ppp_generator/failure_fitness.hpp"

namespace {

using ppp::generator::FailurePanel;

/// The default experiment's hunting panel: wall_follower_left, explorer, bumper, 20 runs each.
FailurePanel defaultPanel(int threads) {
  FailurePanel panel;
  for (const char* type : {"wall_follower_left", "explorer", "bumper"}) {
    ppp::agents::AgentConfig c;
    c.name = c.type = type;
    panel.agents.push_back(c);
  }
  panel.runs_per_eval = 20;
  panel.threads = threads;
  return panel;
}

/// One batch of 16 random solvable 20x20 PPPs (10 descriptors each) scored by the panel.
void BM_FailureBatch(benchmark::State& state) {
  const FailurePanel panel = defaultPanel(static_cast<int>(state.range(0)));
  ppp::Rng rng(1);
  std::vector<ppp::Problem> problems;
  std::vector<ppp::Grid> grids;
  while (problems.size() < 16) {
    ppp::Problem p = ppp::Problem::empty(20, 20, 10);
    p.goal = ppp::Cell{19, 19};
    for (int i = 0; i < 10; ++i) p.obstacles.push_back(ppp::randomObstacle(rng, 20, 20, {}));
    ppp::Grid g = ppp::decodeGrid(p);
    if (!ppp::isReachable(g, p.start, p.goal)) continue;
    problems.push_back(p);
    grids.push_back(g);
  }
  std::vector<const ppp::Problem*> problem_ptrs;
  std::vector<const ppp::Grid*> grid_ptrs;
  for (std::size_t i = 0; i < problems.size(); ++i) {
    problem_ptrs.push_back(&problems[i]);
    grid_ptrs.push_back(&grids[i]);
  }
  for (auto _ : state) benchmark::DoNotOptimize(ppp::generator::estimateFailures(panel, problem_ptrs, grid_ptrs));
  const double episodes = 16.0 * 3 * 20;
  state.counters["PPPs/s"] = benchmark::Counter(16.0 * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["episodes/s"] = benchmark::Counter(episodes * state.iterations(), benchmark::Counter::kIsRate);
}

/// A whole hunt: population 60, `matings` mating events (two evaluations each) against the panel, with
/// the genetic algorithm (crowding window 4, as the default experiment) or the MAP-Elites archive.
void BM_Hunt(benchmark::State& state) {
  ppp::generator::GeneratorOptions options;
  options.fitness = ppp::generator::kFailureFitness;
  options.agents = {"wall_follower_left", "explorer", "bumper"};
  options.matings = state.range(0);
  options.crowding_window = 4;
  options.archive = state.range(1) == 0 ? ppp::generator::kNoArchive : ppp::generator::kMapElitesArchive;
  for (auto _ : state) {
    benchmark::DoNotOptimize(ppp::generator::evolveSet(
        options, ppp::generator::fitnessFor(options, {}, ppp::EpisodeOptions{}, 0)));
  }
  state.SetLabel(options.archive);
  state.counters["evaluations/s"] =
      benchmark::Counter(2.0 * static_cast<double>(options.matings) * state.iterations(), benchmark::Counter::kIsRate);
}

// One thread and every core.
BENCHMARK(BM_FailureBatch)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
// The target: 10,000 evaluations (5,000 matings) x 3 agents x 20 runs in <= 30 s on 2 cores.
BENCHMARK(BM_Hunt)->Args({5000, 0})->Args({5000, 1})->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace
