// Speed of fault hunting in process: the failure fitness's batch scoring and whole hunts.
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_agents/episode_runner.hpp"
#include "ppp_core/diagnosis.hpp"
#include "ppp_core/failure_signature.hpp"
#include "ppp_core/footprint.hpp"
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

/// `count` random solvable 20x20 PPPs (10 descriptors each) and their grids.
void randomProblems(std::size_t count, std::vector<ppp::Problem>* problems, std::vector<ppp::Grid>* grids) {
  ppp::Rng rng(1);
  while (problems->size() < count) {
    ppp::Problem p = ppp::Problem::empty(20, 20, 10);
    p.goal = ppp::Cell{19, 19};
    for (int i = 0; i < 10; ++i) p.obstacles.push_back(ppp::randomObstacle(rng, 20, 20, {}));
    ppp::Grid g = ppp::decodeGrid(p);
    if (!ppp::isReachable(g, p.start, p.goal)) continue;
    problems->push_back(p);
    grids->push_back(g);
  }
}

/// One batch of 16 random solvable 20x20 PPPs scored by the panel.
void BM_FailureBatch(benchmark::State& state) {
  const FailurePanel panel = defaultPanel(static_cast<int>(state.range(0)));
  std::vector<ppp::Problem> problems;
  std::vector<ppp::Grid> grids;
  randomProblems(16, &problems, &grids);
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

/// What a failure signature costs beside the run it describes: the failed runs of the left wall follower (the
/// fastest built-in agent to fail) on 16 random PPPs, played (range 0), or their diagnoses and signatures
/// computed as the failure fitness does for every failed run (1), with each PPP's SignatureMap built too (2).
void BM_FailureSignature(benchmark::State& state) {
  std::vector<ppp::Problem> problems;
  std::vector<ppp::Grid> grids;
  randomProblems(16, &problems, &grids);
  ppp::agents::AgentConfig config;
  config.name = config.type = "wall_follower_left";
  const ppp::EpisodeOptions options;
  ppp::agents::EpisodeRunner runner(config, options);
  const std::unique_ptr<ppp::agents::Agent> agent = ppp::agents::makeAgent(config);
  struct Failed {
    std::size_t problem;
    std::uint64_t seed;
    ppp::EpisodeOutcome outcome;
  };
  std::vector<Failed> failed;
  for (std::size_t p = 0; p < problems.size(); ++p) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      ppp::EpisodeOutcome outcome = runner.run(problems[p], grids[p], *agent, seed, false, nullptr);
      if (!outcome.passed) failed.push_back({p, seed, std::move(outcome)});
    }
  }
  if (failed.empty()) {
    state.SkipWithError("no failed run to sign");
    return;
  }
  std::vector<ppp::SignatureMap> maps;
  for (std::size_t p = 0; p < problems.size(); ++p) {
    ppp::Grid space;
    maps.emplace_back(grids[p], ppp::motionGrid(grids[p], options.robot_radius, &space), problems[p].start,
                      problems[p].goal);
  }
  const bool play = state.range(0) == 0;
  long steps = 0;
  for (auto _ : state) {
    for (const Failed& f : failed) {
      if (play) {
        const ppp::EpisodeOutcome outcome = runner.run(problems[f.problem], grids[f.problem], *agent, f.seed, false,
                                                       nullptr);
        steps += outcome.steps;
        benchmark::DoNotOptimize(outcome.steps);
        continue;
      }
      const ppp::Diagnosis d = ppp::diagnoseRun(false, false, f.outcome.reason, f.outcome.cells);
      benchmark::DoNotOptimize(ppp::failureSignature(maps[f.problem], d, f.outcome.reason, f.outcome.cells));
    }
    if (state.range(0) == 2) {  // the maps too, one per PPP as the failure fitness builds them
      maps.clear();
      for (std::size_t p = 0; p < problems.size(); ++p) {
        ppp::Grid space;
        const ppp::Grid& motion = ppp::motionGrid(grids[p], options.robot_radius, &space);
        maps.emplace_back(grids[p], motion, problems[p].start, problems[p].goal);
      }
    }
  }
  state.SetLabel(play ? "played" : state.range(0) == 1 ? "signed" : "signed, maps built");
  state.counters["failed_runs/s"] = benchmark::Counter(
      static_cast<double>(failed.size()) * state.iterations(), benchmark::Counter::kIsRate);
  if (play) state.counters["moves/run"] = static_cast<double>(steps) / (failed.size() * state.iterations());
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
BENCHMARK(BM_FailureSignature)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
// The target: 10,000 evaluations (5,000 matings) x 3 agents x 20 runs in <= 30 s on 2 cores.
BENCHMARK(BM_Hunt)->Args({5000, 0})->Args({5000, 1})->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace
