// Agent-steps per second through the real episode engine (EpisodeRunner), per agent and map size.
#include <benchmark/benchmark.h>

#include <string>

#include "ppp_core/random_problem.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_simulator/episode.hpp"

namespace {

/// The agent types benchmarked, indexed by the first argument.
const char* const kTypes[] = {"random", "bumper", "explorer", "long_term_explorer", "wall_follower_left", "astar"};

/// Whole episodes (budget 300) of one agent on a random solvable side x side PPP with side/2 obstacles.
void BM_Episodes(benchmark::State& state) {
  const std::string type = kTypes[state.range(0)];
  const int side = static_cast<int>(state.range(1));
  ppp::Rng rng(static_cast<std::uint64_t>(side));
  const ppp::Problem problem = ppp::randomProblem(rng, ppp::Problem::empty(side, side, side / 2), side / 2);
  const ppp::Grid grid = ppp::decodeGrid(problem);
  ppp::agents::AgentConfig config;
  config.type = config.name = type;
  ppp::simulator::EpisodeRunner runner(config, ppp::simulator::EpisodeOptions{});
  auto agent = ppp::agents::makeAgent(config);
  std::uint64_t run = 0;
  std::int64_t steps = 0;
  for (auto _ : state) {
    steps += runner.run(problem, grid, *agent, ++run).steps;
  }
  state.SetLabel(type + " " + std::to_string(side) + "x" + std::to_string(side));
  state.counters["steps/s"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_Episodes)->ArgsProduct({{0, 1, 2, 3, 4, 5}, {20, 50, 100}})->Unit(benchmark::kMicrosecond);

}  // namespace
