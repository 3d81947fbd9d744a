// What lockstep costs per step, with no transport at all. Each of the default experiment's ten built-in agent
// configurations plays the same runs three ways:
//   InProcess    an EpisodeRunner, one episode at a time, as `ppp experiment` plays them;
//   Interleaved  up to `width` episodes at once, one step of each in turn, each agent called directly: what playing
//                many episodes at once costs before any message;
//   Lockstep     batches of up to `batch` episodes through the protocol's messages: an AgentLane writing its scans
//                into a ScanBatch, a BatchResponder answering with a MoveBatch, the lane applying the decoded moves
//                (what the simulator and an agent node do, without ROS).
// Each makes every run into its results.csv row, and the agents are made once (an agent node keeps a pool of them).
// The time is per agent-step; the other two are checked to take the in-process runs' steps.
//   lockstep_bench [--benchmark_filter=explorer]

#include <benchmark/benchmark.h>

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "default_agents.hpp"
#include "ppp_agents/agent_lane.hpp"
#include "ppp_agents/episode_runner.hpp"
#include "ppp_agents/protocol/batch_codec.hpp"
#include "ppp_agents/protocol/batch_responder.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/rng.hpp"

namespace {

constexpr int kProblems = 60;  // a default experiment's set
constexpr int kRuns = 20;      // runs per PPP and agent

/// kProblems random solvable 20x20 PPPs of the generator's kind (10 descriptors), under the default episode rules.
const std::vector<ppp::agents::PreparedSet>& benchSets() {
  static const std::vector<ppp::agents::PreparedSet> sets = [] {
    ppp::ProblemSet set;
    ppp::Rng rng(47);
    for (int p = 0; p < kProblems; ++p) {
      set.ids.push_back("ppp_" + std::to_string(p));
      set.problems.push_back(ppp::randomProblem(rng, ppp::Problem::empty(20, 20, 10), 10));
    }
    return std::vector<ppp::agents::PreparedSet>{ppp::agents::prepareSet("bench", set, ppp::EpisodeOptions{})};
  }();
  return sets;
}

std::uint64_t runSeed(int problem, int run) {
  return ppp::deriveSeed(1, {static_cast<std::uint64_t>(problem), static_cast<std::uint64_t>(run)});
}

/// Every run played in process, one episode at a time, each made into its results.csv row as the lanes make theirs;
/// returns the steps taken.
long playInProcess(const ppp::agents::AgentConfig& config) {
  const ppp::agents::PreparedSet& set = benchSets()[0];
  ppp::agents::EpisodeRunner runner(config, set.episode);
  auto agent = ppp::agents::makeAgent(config);
  long steps = 0;
  for (int p = 0; p < kProblems; ++p) {
    for (int run = 0; run < kRuns; ++run) {
      const std::uint64_t seed = runSeed(p, run);
      const ppp::EpisodeOutcome outcome =
          runner.run(set.set.problems[p], set.grids[p], *agent, seed, false, ppp::agents::windowsOf(set, p));
      steps += ppp::agents::episodeResult(set, p, config.name, run, seed, outcome).steps;
    }
  }
  return steps;
}

/// Agents of one configuration, made once and reset for each episode.
using AgentPool = std::vector<std::unique_ptr<ppp::agents::Agent>>;

/// Every run played in rounds over up to `width` episodes, one step of each per round, each episode answered by an
/// agent of `pool` (grown to `width`) called directly, and made into its row as it ends; returns the steps taken.
long playInterleaved(const ppp::agents::AgentConfig& config, int width, AgentPool* pool) {
  const ppp::agents::PreparedSet& set = benchSets()[0];
  const ppp::SensorModel sensor(ppp::SensorOptions{set.episode.sensor_range, config.sensor_noise});
  while (static_cast<int>(pool->size()) < width) pool->push_back(ppp::agents::makeAgent(config));
  std::vector<ppp::agents::Agent*> idle;
  for (const auto& agent : *pool) idle.push_back(agent.get());
  struct Active {
    int problem;
    int run;
    std::uint64_t seed;
    ppp::Episode episode;
    ppp::agents::Agent* agent;
  };
  std::deque<std::pair<int, int>> queue;  // (PPP, run) still to play
  for (int p = 0; p < kProblems; ++p) {
    for (int run = 0; run < kRuns; ++run) queue.emplace_back(p, run);
  }
  std::vector<Active> active;
  long steps = 0;
  while (!queue.empty() || !active.empty()) {
    while (static_cast<int>(active.size()) < width && !queue.empty()) {
      const auto [p, run] = queue.front();
      queue.pop_front();
      ppp::agents::Agent* agent = idle.back();
      idle.pop_back();
      const std::uint64_t seed = runSeed(p, run);
      agent->reset(ppp::agents::episodeInfo(set.set.problems[p], set.grids[p], config, seed, set.episode.connectivity,
                                            ppp::agents::motionOf(set, p)));
      active.push_back({p, run, seed,
                        ppp::Episode(set.set.problems[p], set.grids[p], sensor, seed,
                                     set.episode.budgetRule(set.budgets[p]), set.episode.connectivity, false,
                                     ppp::agents::windowsOf(set, p), ppp::agents::motionOf(set, p)),
                        agent});
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < active.size(); ++i) {
      Active& a = active[i];
      a.episode.apply(a.agent->act(a.episode.scan()));
      if (a.episode.done()) {
        steps += ppp::agents::episodeResult(set, a.problem, config.name, a.run, a.seed, a.episode.outcome()).steps;
        idle.push_back(a.agent);
      } else {
        if (kept != i) active[kept] = std::move(a);
        ++kept;
      }
    }
    active.erase(active.begin() + static_cast<std::ptrdiff_t>(kept), active.end());
  }
  return steps;
}

/// Every run played in lockstep batches of `batch_size` through the protocol's messages, answered by `responder`
/// (an agent node's, which keeps its pool of agents from lane to lane); returns the steps taken.
long playInLockstep(const ppp::agents::AgentConfig& config, int batch_size,
                    ppp::protocol::BatchResponder* responder) {
  const std::vector<ppp::agents::PreparedSet>& sets = benchSets();
  ppp::agents::AgentLane lane(config, sets[0].episode, sets, [](int, int p, int run) { return runSeed(p, run); },
                              kRuns, batch_size);
  long steps = 0;
  std::uint32_t batch = 0;
  while (!lane.finished()) {
    ppp_msgs::ScanBatch scans;  // a new message per round trip, as the simulator publishes
    scans.agent = config.name;
    scans.batch = ++batch;
    ppp::protocol::ScanBatchWriter writer(&scans);
    lane.scans(&writer);
    const ppp::protocol::DecodedMoves moves = ppp::protocol::decodeMoves(responder->answer(scans));
    for (const ppp::agents::EpisodeResult& ended : lane.answer(moves.moves, moves.missing_reason)) {
      steps += ended.steps;
    }
  }
  return steps;
}

/// Reports the time per step, labelled; or fails the benchmark when the runs took other steps than in process.
void reportSteps(benchmark::State& state, long steps, long in_process_steps, const std::string& label) {
  if (steps != in_process_steps) {
    state.SkipWithError("the runs took other steps than the in-process runs");
    return;
  }
  state.counters["per_step"] = benchmark::Counter(static_cast<double>(steps),
                                                  benchmark::Counter::kIsIterationInvariantRate |
                                                      benchmark::Counter::kInvert);
  state.SetLabel(label);
}

void BM_InProcess(benchmark::State& state) {
  const ppp::agents::AgentConfig config = ppp::bench::defaultAgent(static_cast<int>(state.range(0)));
  long steps = 0;
  for (auto _ : state) steps = playInProcess(config);
  reportSteps(state, steps, steps, config.name);
}
BENCHMARK(BM_InProcess)->DenseRange(0, ppp::bench::kDefaultAgentCount - 1)->Unit(benchmark::kMillisecond);

void BM_Interleaved(benchmark::State& state) {
  const ppp::agents::AgentConfig config = ppp::bench::defaultAgent(static_cast<int>(state.range(0)));
  const int width = static_cast<int>(state.range(1));
  const long expected = playInProcess(config);
  AgentPool pool;
  long steps = 0;
  for (auto _ : state) steps = playInterleaved(config, width, &pool);
  reportSteps(state, steps, expected, config.name + ", " + std::to_string(width) + " at once");
}
BENCHMARK(BM_Interleaved)
    ->ArgsProduct({benchmark::CreateDenseRange(0, ppp::bench::kDefaultAgentCount - 1, 1), {32, 500}})
    ->Unit(benchmark::kMillisecond);

void BM_Lockstep(benchmark::State& state) {
  const ppp::agents::AgentConfig config = ppp::bench::defaultAgent(static_cast<int>(state.range(0)));
  const int batch_size = static_cast<int>(state.range(1));
  const long expected = playInProcess(config);
  ppp::protocol::BatchResponder responder(config);
  playInLockstep(config, batch_size, &responder);  // the agent pool filled, as in an agent node that ran a while
  long steps = 0;
  for (auto _ : state) steps = playInLockstep(config, batch_size, &responder);
  reportSteps(state, steps, expected, config.name + ", batches of " + std::to_string(batch_size));
}
BENCHMARK(BM_Lockstep)
    ->ArgsProduct({benchmark::CreateDenseRange(0, ppp::bench::kDefaultAgentCount - 1, 1), {8, 32, 128, 500}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
