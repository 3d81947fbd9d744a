// Control steps per second of the continuous motion model: each step casts the default laser (360 beams, 3.5 m),
// asks the agent (the continuous A*, planning and following by pure pursuit) for its command, limits it, moves
// the disc along its exact arc and checks for contact. Runs on 20 random solvable 20x20 PPPs (10 descriptors,
// seed 20), a disc of 0.2 cells, diff drive and holonomic; a run starts again when it ends.
//   continuous_step_bench [--benchmark_repetitions=3]

#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "ppp_agents/continuous/continuous_agent.hpp"
#include "ppp_agents/continuous/continuous_runner.hpp"
#include "ppp_core/continuous_episode.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/reachability.hpp"
#include "ppp_core/rng.hpp"

namespace {

struct BenchMap {
  ppp::Problem problem;
  ppp::Grid grid;
  long budget;
};

std::vector<BenchMap> benchMaps(const ppp::EpisodeOptions& options) {
  std::vector<BenchMap> maps;
  ppp::Rng rng(20);
  for (int i = 0; i < 20; ++i) {
    BenchMap map;
    map.problem = ppp::randomProblem(rng, ppp::Problem::empty(20, 20, 10), 10);
    map.grid = ppp::decodeGrid(map.problem);
    const int moves = ppp::fewestMoves(map.grid, map.problem.start, map.problem.goal, ppp::Connectivity::Four);
    map.budget = ppp::continuousStepBudget(
        options.motion, ppp::agents::continuousOptimalMoves(map.problem, map.grid, options, moves));
    maps.push_back(std::move(map));
  }
  return maps;
}

void controlSteps(benchmark::State& state, const char* kinematics) {
  ppp::EpisodeOptions options;
  options.motion.motion = ppp::kMotionContinuous;
  options.motion.kinematics = kinematics;
  options.robot_radius = 0.2;
  const std::vector<BenchMap> maps = benchMaps(options);
  ppp::agents::AgentConfig config;
  config.name = config.type = "astar";
  std::unique_ptr<ppp::agents::ContinuousAgent> agent = ppp::agents::makeContinuousAgent(config);
  std::vector<float> ranges;
  std::size_t next = 0;
  std::unique_ptr<ppp::ContinuousEpisode> run;
  long steps = 0;
  for (auto _ : state) {
    if (!run || run->done()) {
      const BenchMap& map = maps[next++ % maps.size()];
      run = std::make_unique<ppp::ContinuousEpisode>(map.problem, map.grid, options.motion, options.robot_radius,
                                                     map.budget, 1);
      ppp::agents::ContinuousStart start;
      start.frame = run->world().frame();
      start.pose = run->pose();
      start.goal = run->goal();
      start.radius = run->radius();
      start.limits = run->limits();
      start.beams = run->beams();
      start.prior_map = &map.grid;
      agent->start(start);
    }
    run->scan(&ranges);
    const ppp::agents::ContinuousSensing sensing{run->pose(), run->velocity(), run->time(), &ranges};
    run->apply(agent->command(sensing));
    benchmark::DoNotOptimize(ranges.data());
    ++steps;
  }
  state.SetItemsProcessed(steps);
}

}  // namespace

BENCHMARK_CAPTURE(controlSteps, diff_drive, ppp::kKinematicsDiffDrive);
BENCHMARK_CAPTURE(controlSteps, holonomic, ppp::kKinematicsHolonomic);
BENCHMARK_MAIN();
