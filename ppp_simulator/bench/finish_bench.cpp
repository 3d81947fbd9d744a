// The serial tail of an experiment of the default experiment's shape (3 sets x 60 PPPs x 10 built-in agents x
// 1,000 runs = 1.8 million rows, results.csv about 160 MB): finishExperiment (results.csv read, put in canonical
// order and rewritten if it is not, summary.csv and the report) on rows in canonical order (/0: as ppp experiment
// writes them) and on rows in the order two workers finish their units (/1: a resume, the ROS simulator), its
// parts (parsing, the report), and the resume's reading of the finished file (ResultsFile opened on it).
//   finish_bench [--benchmark_repetitions=3]

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <tuple>
#include <filesystem>
#include <string>
#include <vector>

#include "ppp_core/random_problem.hpp"
#include "ppp_core/reachability.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_simulator/experiment_report.hpp"
#include "ppp_simulator/experiment_runner.hpp"
#include "ppp_simulator/results_file.hpp"

namespace {

namespace fs = std::filesystem;
namespace sim = ppp::simulator;

constexpr int kSets = 3;
constexpr int kProblems = 60;
constexpr int kRuns = 1000;

/// The default experiment's ten built-in agents.
ppp::simulator::ExperimentConfig benchConfig() {
  sim::ExperimentConfig config;
  config.runs = kRuns;
  const std::vector<std::pair<const char*, const char*>> agents = {
      {"astar", "astar"},
      {"random", "random"},
      {"wall_follower_left", "wall_follower_left"},
      {"wall_follower_right", "wall_follower_right"},
      {"explorer", "explorer"},
      {"long_term_explorer", "long_term_explorer"},
      {"explorer_memory_5x5", "explorer"},
      {"explorer_noise_0.1", "explorer"},
      {"bumper", "bumper"},
      {"decision_bumper", "decision_bumper"}};
  for (const auto& [name, type] : agents) {
    ppp::agents::AgentConfig agent;
    agent.name = name;
    agent.type = type;
    if (agent.name == "explorer_memory_5x5") agent.memory_window = 5;
    if (agent.name == "explorer_noise_0.1") agent.sensor_noise = 0.1;
    config.agents.push_back(agent);
  }
  for (int s = 0; s < kSets; ++s) config.sets.push_back(sim::SetSpec{"set" + std::to_string(s), {}, ""});
  return config;
}

/// The position of an agent in benchConfig().
int agentPosition(const std::string& name) {
  static const sim::ExperimentConfig config = benchConfig();
  for (std::size_t i = 0; i < config.agents.size(); ++i) {
    if (config.agents[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

/// kSets sets of kProblems random solvable 20x20 PPPs.
std::vector<ppp::agents::PreparedSet> benchSets() {
  ppp::Rng rng(7);
  std::vector<ppp::agents::PreparedSet> sets;
  for (int s = 0; s < kSets; ++s) {
    ppp::ProblemSet set;
    set.fitness = "random";
    while (static_cast<int>(set.problems.size()) < kProblems) {
      ppp::Problem p = ppp::Problem::empty(20, 20, 20);
      p.goal = ppp::Cell{19, 19};
      for (int i = 0; i < 20; ++i) p.obstacles.push_back(ppp::randomObstacle(rng, 20, 20, {}));
      if (!ppp::isReachable(ppp::decodeGrid(p), p.start, p.goal)) continue;
      char id[16];
      std::snprintf(id, sizeof id, "ppp_%03d", static_cast<int>(set.problems.size()));
      set.ids.push_back(id);
      set.problems.push_back(p);
    }
    sets.push_back(ppp::agents::prepareSet("set" + std::to_string(s), set, ppp::EpisodeOptions{}));
  }
  return sets;
}

/// results.csv as two workers leave it: each (set, PPP, agent) unit's rows in one block, the units of a pair
/// finishing in either order; outcomes drawn per unit with a pass probability of its own.
std::string unorderedResults(const sim::ExperimentConfig& config, const std::vector<ppp::agents::PreparedSet>& sets) {
  const std::string path = (fs::temp_directory_path() / "ppp_finish_bench_rows.csv").string();
  fs::remove(path);
  {
    sim::ResultsFile file(path);
    ppp::Rng rng(3);
    std::vector<ppp::agents::EpisodeResult> pending;
    for (int s = 0; s < kSets; ++s) {
      for (int p = 0; p < kProblems; ++p) {
        for (const auto& agent : config.agents) {
          const double pass_probability = static_cast<double>(rng.below(101)) / 100.0;
          std::vector<ppp::agents::EpisodeResult> rows;
          for (int run = 0; run < kRuns; ++run) {
            ppp::EpisodeOutcome outcome;
            outcome.passed = static_cast<double>(rng.below(1000)) < 1000.0 * pass_probability;
            outcome.steps = outcome.passed ? 20 + static_cast<int>(rng.below(200)) : 300;
            outcome.bumps = static_cast<int>(rng.below(40)) % (outcome.steps + 1);  // never more than the steps
            outcome.path_length = outcome.steps - outcome.bumps;
            outcome.reason = outcome.passed ? ppp::reason::kGoalReached : ppp::reason::kBudgetExhausted;
            const std::uint64_t seed = sim::runSeed(config.seed, sets[s].name, sets[s].set.ids[p], agent.name, run);
            rows.push_back(ppp::agents::episodeResult(sets[s], p, agent.name, run, seed, outcome));
          }
          if (rng.below(2) == 0) {
            file.append(rows);
          } else {  // this unit finishes after the next one
            if (!pending.empty()) file.append(pending);
            pending = std::move(rows);
          }
        }
      }
    }
    if (!pending.empty()) file.append(pending);
  }
  const std::string text = ppp::readTextFile(path, std::size_t{1} << 31);
  fs::remove(path);
  return text;
}

/// The same rows in canonical order.
std::string orderedResults(const std::string& unordered) {
  std::vector<ppp::agents::EpisodeResult> rows = sim::parseResultsCsv(unordered, "results.csv");
  std::stable_sort(rows.begin(), rows.end(), [](const ppp::agents::EpisodeResult& a, const ppp::agents::EpisodeResult& b) {
    const auto set = [](const std::string& name) { return std::stoi(name.substr(3)); };
    return std::make_tuple(set(a.set), a.problem, agentPosition(a.agent), a.run) <
           std::make_tuple(set(b.set), b.problem, agentPosition(b.agent), b.run);
  });
  std::string text = "set,problem,agent,run,seed,pass,steps,bumps,path_length,optimal_length,reason\n";
  for (const ppp::agents::EpisodeResult& r : rows) ppp::agents::appendCsvRow(r, &text);
  return text;
}

struct Fixture {
  sim::ExperimentConfig config = benchConfig();
  std::vector<ppp::agents::PreparedSet> sets = benchSets();
  std::string unordered = unorderedResults(config, sets);
  std::string ordered = orderedResults(unordered);
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

void BM_FinishExperiment(benchmark::State& state) {
  const Fixture& f = fixture();
  const fs::path dir = fs::temp_directory_path() / "ppp_finish_bench";
  fs::remove_all(dir);
  fs::create_directories(dir);
  sim::ResultsFile results(sim::resultsPath(dir.string()));
  const std::string& rows = state.range(0) == 0 ? f.ordered : f.unordered;
  for (auto _ : state) {
    state.PauseTiming();
    ppp::writeFileAtomically(sim::resultsPath(dir.string()), rows);
    state.ResumeTiming();
    sim::finishExperiment(f.config, "bench", dir.string(), f.sets, &results);
  }
  state.counters["rows/s"] =
      benchmark::Counter(static_cast<double>(kSets) * kProblems * 10 * kRuns * state.iterations(),
                         benchmark::Counter::kIsRate);
  fs::remove_all(dir);
}
BENCHMARK(BM_FinishExperiment)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(0.1);

void BM_ParseResults(benchmark::State& state) {
  const Fixture& f = fixture();
  for (auto _ : state) benchmark::DoNotOptimize(sim::parseResultsCsv(f.unordered, "results.csv").size());
}
BENCHMARK(BM_ParseResults)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(0.1);

void BM_Report(benchmark::State& state) {
  const Fixture& f = fixture();
  const std::vector<ppp::agents::EpisodeResult> rows = sim::parseResultsCsv(f.ordered, "results.csv");
  const fs::path dir = fs::temp_directory_path() / "ppp_report_bench";
  for (auto _ : state) sim::writeExperimentReport(dir.string(), f.config, "bench", f.sets, rows);
  fs::remove_all(dir);
}
BENCHMARK(BM_Report)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(0.1);

void BM_ResumeRead(benchmark::State& state) {
  const Fixture& f = fixture();
  const fs::path dir = fs::temp_directory_path() / "ppp_resume_bench";
  fs::remove_all(dir);
  fs::create_directories(dir);
  ppp::writeFileAtomically(sim::resultsPath(dir.string()), f.unordered);
  for (auto _ : state) {
    sim::ResultsFile results(sim::resultsPath(dir.string()));
    benchmark::DoNotOptimize(results.done().size());
  }
  fs::remove_all(dir);
}
BENCHMARK(BM_ResumeRead)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(0.1);

}  // namespace
