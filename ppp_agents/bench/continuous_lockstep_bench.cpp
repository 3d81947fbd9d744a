// What continuous motion's lockstep protocol costs before any transport: the same runs of the continuous A* control
// played in process one at a time (ContinuousRunner, as `ppp experiment` plays them) and in lockstep batches through
// the protocol's messages without ROS (a ContinuousLane writes a ppp_msgs/SensingBatch, a ContinuousResponder kept
// for the whole lane answers with a ppp_msgs/CommandBatch, the lane applies the decoded commands), as an agent node
// answers the simulator in one nodelet manager. Runs on 60 random solvable 20x20 PPPs (10 descriptors, seed 20),
// 4 runs each, a disc of 0.2 cells; time per control period (the counter "per_period").
//   continuous_lockstep_bench [--benchmark_repetitions=3]

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "ppp_agents/continuous/continuous_lane.hpp"
#include "ppp_agents/continuous/continuous_runner.hpp"
#include "ppp_agents/protocol/continuous_codec.hpp"
#include "ppp_agents/protocol/continuous_responder.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/rng.hpp"

namespace {

constexpr int kRuns = 4;

ppp::EpisodeOptions benchOptions() {
  ppp::EpisodeOptions options;
  options.motion.motion = ppp::kMotionContinuous;
  options.robot_radius = 0.2;
  return options;
}

ppp::agents::AgentConfig astar() {
  ppp::agents::AgentConfig config;
  config.name = config.type = "astar";
  return config;
}

const std::vector<ppp::agents::PreparedSet>& benchSets() {
  static const std::vector<ppp::agents::PreparedSet> sets = [] {
    ppp::Rng rng(20);
    ppp::ProblemSet set;
    for (int i = 0; i < 60; ++i) {
      set.ids.push_back("ppp_" + std::to_string(i));
      set.problems.push_back(ppp::randomProblem(rng, ppp::Problem::empty(20, 20, 10), 10));
    }
    return std::vector<ppp::agents::PreparedSet>{ppp::agents::prepareSet("bench", set, benchOptions())};
  }();
  return sets;
}

std::uint64_t seedOf(int, int problem, int run) { return ppp::deriveSeed(7, {std::uint64_t(problem), std::uint64_t(run)}); }

void inProcess(benchmark::State& state) {
  const auto& sets = benchSets();
  ppp::agents::ContinuousRunner runner(astar(), benchOptions());
  long periods = 0;
  for (auto _ : state) {
    for (int p = 0; p < static_cast<int>(sets[0].set.problems.size()); ++p) {
      for (int run = 0; run < kRuns; ++run) periods += runner.row(sets[0], p, run, seedOf(0, p, run)).steps;
    }
  }
  state.counters["per_period"] = benchmark::Counter(static_cast<double>(periods),
                                                    benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void lockstep(benchmark::State& state) {
  const auto& sets = benchSets();
  const int batch = static_cast<int>(state.range(0));
  ppp::protocol::ContinuousResponder responder(astar());
  std::vector<ppp::agents::ContinuousRequest> requests;
  long periods = 0;
  for (auto _ : state) {
    ppp::agents::ContinuousLane lane(astar(), benchOptions(), sets, seedOf, kRuns, batch);
    std::uint32_t round = 0;
    while (!lane.finished()) {
      lane.requests(&requests);
      periods += static_cast<long>(requests.size());
      ppp_msgs::SensingBatch sensing;
      sensing.batch = ++round;
      ppp::protocol::encodeSensing(requests, &sensing);
      const ppp::protocol::DecodedCommands commands = ppp::protocol::decodeCommands(responder.answer(sensing));
      benchmark::DoNotOptimize(lane.answer(commands.replies, commands.missing_reason));
    }
  }
  state.counters["per_period"] = benchmark::Counter(static_cast<double>(periods),
                                                    benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK(inProcess)->Unit(benchmark::kMillisecond);
BENCHMARK(lockstep)->Arg(32)->Arg(128)->Arg(500)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
