// Steps per second of each agent configuration on a 20x20 PPP, with the move model applied in a tiny loop
// (the scan is built lazily from the map's window atlas, as the in-process engine and the simulator do):
// reset at the goal or after 300 steps.
//   agent_step_bench [--benchmark_repetitions=3]

#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/sensor.hpp"
#include "ppp_core/window_atlas.hpp"

namespace {

using ppp::Cell;
using ppp::agents::AgentConfig;

/// The benchmark map: the core benchmarks' 20x20 problem (10 random descriptors, seed 20).
const ppp::Problem& benchProblem() {
  static const ppp::Problem problem = [] {
    ppp::Rng rng(20);
    return ppp::randomProblem(rng, ppp::Problem::empty(20, 20, 10), 10);
  }();
  return problem;
}

void agentSteps(benchmark::State& state, AgentConfig config) {
  const ppp::Problem& problem = benchProblem();
  const ppp::Grid grid = ppp::decodeGrid(problem);
  const ppp::SensorModel sensor(ppp::SensorOptions{2, config.sensor_noise});
  const ppp::WindowAtlas windows(grid, sensor.options().range);
  std::unique_ptr<ppp::agents::Agent> agent = ppp::agents::makeAgent(config);
  ppp::agents::EpisodeInfo info;
  info.width = grid.width();
  info.height = grid.height();
  info.start = problem.start;
  info.goal = problem.goal;
  info.prior_map = config.type == "astar" ? &grid : nullptr;
  std::uint64_t episode = 0;
  info.seed = ppp::deriveSeed(7, {episode});
  agent->reset(info);
  Cell position = problem.start;
  bool bumped = false;
  int step = 0;
  std::int64_t passes = 0;
  for (auto _ : state) {
    const ppp::Scan scan(sensor, grid, position, problem.goal, bumped, step, info.seed, &windows);
    const ppp::Action action = agent->act(scan);
    const Cell next = ppp::target(position, action);
    bumped = action != ppp::Action::Stay && !grid.isFree(next);
    if (!bumped) position = next;
    ++step;
    if (position == problem.goal || step == 300) {
      passes += position == problem.goal ? 1 : 0;
      info.seed = ppp::deriveSeed(7, {++episode});
      agent->reset(info);
      position = problem.start;
      bumped = false;
      step = 0;
    }
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["episodes"] = static_cast<double>(episode);
  state.counters["pass_rate"] = episode > 0 ? static_cast<double>(passes) / static_cast<double>(episode) : 0.0;
}

const bool registered = [] {
  std::vector<AgentConfig> configs;
  for (const std::string& type : ppp::agents::agentTypeNames()) {
    AgentConfig c;
    c.name = type;
    c.type = type;
    configs.push_back(c);
  }
  AgentConfig memory;
  memory.name = "explorer_memory_5x5";
  memory.type = "explorer";
  memory.memory_window = 5;
  configs.push_back(memory);
  AgentConfig noise;
  noise.name = "explorer_noise_0.1";
  noise.type = "explorer";
  noise.sensor_noise = 0.1;
  configs.push_back(noise);
  for (const AgentConfig& c : configs) {
    benchmark::RegisterBenchmark(("agent_step/" + c.name).c_str(), agentSteps, c);
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
