// Agent-steps per second through the real episode engine (EpisodeRunner), per agent and map size; and the cost
// of animating one episode for the report.
#include <benchmark/benchmark.h>

#include <string>

#include "ppp_core/random_problem.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_agents/episode_runner.hpp"
#include "ppp_simulator/report/episode_animation.hpp"

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
  ppp::agents::EpisodeRunner runner(config, ppp::EpisodeOptions{});
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

/// One failing episode of the random agent animated (12 pixels per cell on 20x20, frames of 241 x 241 pixels,
/// at most 1,001 of them, encoded as a GIF) with the budget given as the argument: 300 (301 frames, as in the
/// report) and 100,000 (every 100th step); the label gives the frames and the GIF's size.
void BM_AnimateEpisode(benchmark::State& state) {
  ppp::Rng rng(20);
  const ppp::Problem problem = ppp::randomProblem(rng, ppp::Problem::empty(20, 20, 10), 10);
  const ppp::Grid grid = ppp::decodeGrid(problem);
  ppp::agents::AgentConfig config;
  config.type = config.name = "random";
  std::size_t bytes = 0;
  int frames = 0;
  ppp::EpisodeOptions options;
  options.budget = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const auto animation = ppp::simulator::animateEpisode(problem, grid, config, options, 1);
    bytes = animation.gif.size();
    frames = animation.frames;
  }
  state.SetLabel(std::to_string(frames) + " frames, " + std::to_string(bytes / 1024) + " KiB");
}

BENCHMARK(BM_AnimateEpisode)->Arg(300)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
