#include "ppp_simulator/experiment_runner.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <unordered_map>

#include "ppp_core/dpa.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_simulator/episode.hpp"
#include "ppp_simulator/experiment_report.hpp"
#include "ppp_simulator/results_file.hpp"
#include "ppp_generator/set_evolution.hpp"
#include "ppp_simulator/failure_fitness.hpp"

namespace ppp {
namespace simulator {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFingerprintFile = "experiment.yaml";
constexpr const char* kResultsFile = "results.csv";
constexpr std::size_t kRowsPerStopCheck = 1 << 14;  // rows handled between two questions to the StopCheck

/// One batch of work: every remaining run of one agent on one PPP.
struct Unit {
  int set;
  int problem;
  int agent;
  std::vector<int> runs;
};

void say(const std::function<void(const std::string&)>& log, const std::string& text) {
  if (log) log(text);
}

/// Positions of names, asked row after row: the previous answer is kept, since consecutive rows mostly name the
/// same set, PPP and agent.
class NameIndex {
 public:
  /// The position of `name`, or -1 when it is not listed.
  int find(const std::string& name) {
    if (last_ != nullptr && *last_ == name) return last_index_;
    const auto it = index_.find(name);
    if (it == index_.end()) return -1;
    last_ = &it->first;
    last_index_ = it->second;
    return last_index_;
  }
  /// Lists `name` at `position` (a name listed twice keeps its first position).
  void add(const std::string& name, int position) { index_.emplace(name, position); }

 private:
  std::unordered_map<std::string, int> index_;
  const std::string* last_ = nullptr;
  int last_index_ = -1;
};

/// Each row's problem id as its rank in text order among every id of the sets and of the rows.
/// @throws Interrupted.
std::vector<int> problemRanks(const std::vector<EpisodeResult>& rows, const std::vector<PreparedSet>& sets,
                              const StopCheck& stop) {
  std::unordered_map<std::string, int> distinct;
  for (const PreparedSet& set : sets) {
    for (const std::string& id : set.set.ids) distinct.emplace(id, static_cast<int>(distinct.size()));
  }
  std::vector<int> problem_of_row(rows.size());
  const std::string* last = nullptr;
  int last_index = -1;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i % kRowsPerStopCheck == 0) stopIfAsked(stop);
    if (last == nullptr || *last != rows[i].problem) {
      const auto [it, added] = distinct.emplace(rows[i].problem, static_cast<int>(distinct.size()));
      last = &it->first;
      last_index = it->second;
    }
    problem_of_row[i] = last_index;
  }
  std::vector<std::pair<const std::string*, int>> by_text;
  for (const auto& [id, index] : distinct) by_text.emplace_back(&id, index);
  std::sort(by_text.begin(), by_text.end(), [](const auto& a, const auto& b) { return *a.first < *b.first; });
  std::vector<int> rank(by_text.size());
  for (std::size_t r = 0; r < by_text.size(); ++r) {
    rank[static_cast<std::size_t>(by_text[r].second)] = static_cast<int>(r);
  }
  for (int& problem : problem_of_row) problem = rank[static_cast<std::size_t>(problem)];
  return problem_of_row;
}

/// Puts `rows` in canonical order (set, PPP, agent, run as the config lists them), so the finished results.csv
/// does not depend on threads, batches or interruptions; returns whether any row moved.
/// @throws ParseError (a row of another experiment), Interrupted.
bool putInCanonicalOrder(std::vector<EpisodeResult>* rows, const ExperimentConfig& config,
                         const std::vector<PreparedSet>& sets, const std::string& path, const StopCheck& stop) {
  NameIndex set_order, agent_order;
  for (std::size_t i = 0; i < sets.size(); ++i) set_order.add(sets[i].name, static_cast<int>(i));
  for (std::size_t i = 0; i < config.agents.size(); ++i) agent_order.add(config.agents[i].name, static_cast<int>(i));
  const std::vector<int> problem_rank = problemRanks(*rows, sets, stop);
  // Each row's (set, problem, agent, run) positions, looked up once, then ordered as plain numbers.
  std::vector<std::pair<std::array<int, 4>, std::size_t>> keys(rows->size());
  for (std::size_t i = 0; i < rows->size(); ++i) {
    if (i % kRowsPerStopCheck == 0) stopIfAsked(stop);
    const EpisodeResult& row = (*rows)[i];
    const int set = set_order.find(row.set);
    const int agent = agent_order.find(row.agent);
    if (set < 0 || agent < 0) {
      throw ParseError(path, 0, "row",
                       "run of set '" + row.set + "', agent '" + row.agent + "' is not part of this experiment");
    }
    keys[i] = {{set, problem_rank[i], agent, row.run}, i};
  }
  stopIfAsked(stop);
  // A run that was not interrupted wrote its rows in canonical order (OrderedAppender): nothing to move then.
  const auto not_rising = [](const auto& a, const auto& b) { return !(a.first < b.first); };
  if (std::adjacent_find(keys.begin(), keys.end(), not_rising) == keys.end()) return false;
  std::sort(keys.begin(), keys.end());
  std::vector<EpisodeResult> sorted;
  sorted.reserve(rows->size());
  for (const auto& key : keys) sorted.push_back(std::move((*rows)[key.second]));
  *rows = std::move(sorted);
  return true;
}

}  // namespace

std::uint64_t runSeed(std::uint64_t experiment_seed, const std::string& set, const std::string& problem,
                      const std::string& agent, int run) {
  return deriveSeed(experiment_seed,
                    {nameHash(set), nameHash(problem), nameHash(agent), static_cast<std::uint64_t>(run)});
}

EpisodeResult episodeResult(const PreparedSet& set, int problem, const std::string& agent, int run,
                            std::uint64_t seed, const EpisodeOutcome& outcome) {
  EpisodeResult r;
  r.set = set.name;
  r.problem = set.set.ids[problem];
  r.agent = agent;
  r.run = run;
  r.seed = seed;
  r.passed = outcome.passed;
  r.steps = outcome.steps;
  r.bumps = outcome.bumps;
  r.path_length = outcome.path_length;
  r.optimal_length = set.optimal[problem];
  r.reason = outcome.reason;
  return r;
}

void checkExperimentDirectory(const ExperimentConfig& config, const std::string& dir) {
  const fs::path root(dir);
  std::error_code error;
  if (!fs::exists(root, error)) return;
  if (!fs::is_directory(root)) throw IoError(dir, "exists and is not a directory");
  if (fs::is_empty(root, error)) return;
  const fs::path fingerprint = root / kFingerprintFile;
  // A new experiment may find only sets/ (written by generator nodes started beside the simulator).
  const bool only_sets = std::all_of(fs::directory_iterator(root), fs::directory_iterator(),
                                     [](const fs::directory_entry& e) { return e.path().filename() == "sets"; });
  if (!fs::exists(fingerprint) && only_sets) return;
  if (!fs::exists(fingerprint)) {
    throw IoError(dir, "holds files but no " + std::string(kFingerprintFile) +
                           "; refusing to write an experiment over something else");
  }
  const std::string stored = readTextFile(fingerprint.string(), 1u << 20);
  const std::string wanted = experimentFingerprint(config);
  if (stored == wanted) return;
  std::size_t line = 1;
  std::size_t i = 0;
  for (; i < std::min(stored.size(), wanted.size()) && stored[i] == wanted[i]; ++i) line += stored[i] == '\n';
  throw IoError(dir, "holds a different experiment (" + fingerprint.string() + " differs from this configuration at line " +
                         std::to_string(line) + "); use another output directory");
}

PreparedSet prepareSet(const std::string& name, generator::ProblemSet set, int sensor_range) {
  PreparedSet p;
  p.name = name;
  p.set = std::move(set);
  DpaSolver dpa;
  for (const Problem& problem : p.set.problems) {
    p.grids.push_back(decodeGrid(problem));
    const DpaResult& result = dpa.solve(p.grids.back(), problem.start, problem.goal);
    if (!result.reachable) throw InvalidArgument("sets", "set '" + name + "' holds an unsolvable PPP");
    p.optimal.push_back(result.advances);
    p.windows.push_back(WindowAtlas::bytes(p.grids.back(), sensor_range) <= kMaxWindowAtlasBytes
                            ? std::optional<WindowAtlas>(std::in_place, p.grids.back(), sensor_range)
                            : std::nullopt);
  }
  return p;
}

std::vector<PreparedSet> prepareSets(const ExperimentConfig& config, const std::string& dir,
                                     const std::function<void(const std::string&)>& log, const StopCheck& stop) {
  std::vector<PreparedSet> prepared;
  for (const SetSpec& spec : config.sets) {
    std::string set_dir = spec.directory;
    if (spec.generator) {
      set_dir = (fs::path(dir) / "sets" / spec.name).string();
      if (!fs::exists(fs::path(set_dir) / "set.csv")) {
        say(log, "generating set '" + spec.name + "' (" + spec.generator->fitness + ", " +
                     std::to_string(spec.generator->matings) + " matings)");
        generator::Fitness fitness;
        try {
          fitness = fitnessFor(*spec.generator, config.agents, config.episode, config.threads);
        } catch (const InvalidArgument& e) {
          throw InvalidArgument("sets", "set '" + spec.name + "': " + e.what());
        }
        const generator::EvolvedSet evolved = generator::evolveSetDirectory(set_dir, *spec.generator, fitness, {}, stop);
        say(log, "set '" + spec.name + "': " + evolved.summary);
      }
    }
    PreparedSet p = prepareSet(spec.name, generator::readProblemSetDirectory(set_dir), config.episode.sensor_range);
    p.directory = set_dir;
    prepared.push_back(std::move(p));
  }
  return prepared;
}

void openExperimentDirectory(const ExperimentConfig& config, const std::string& dir) {
  config.validate();
  checkExperimentDirectory(config, dir);
  fs::create_directories(dir);
  writeFileAtomically((fs::path(dir) / kFingerprintFile).string(), experimentFingerprint(config));
}

std::vector<PreparedSet> beginExperiment(const ExperimentConfig& config, const std::string& dir,
                                         const std::function<void(const std::string&)>& log, const StopCheck& stop) {
  openExperimentDirectory(config, dir);
  return prepareSets(config, dir, log, stop);
}

std::string resultsPath(const std::string& dir) { return (fs::path(dir) / kResultsFile).string(); }

void finishExperiment(const ExperimentConfig& config, const std::string& config_text, const std::string& dir,
                      const std::vector<PreparedSet>& sets, ResultsFile* results, const StopCheck& stop,
                      const std::function<void(const std::string&)>& log) {
  stopIfAsked(stop);
  say(log, "finishing: results.csv in run order");
  std::vector<EpisodeResult> rows = readResultsFile(resultsPath(dir), stop);
  const std::size_t read = rows.size();
  rows = standingRows(std::move(rows));
  const bool moved = putInCanonicalOrder(&rows, config, sets, resultsPath(dir), stop);
  stopIfAsked(stop);
  if (moved || rows.size() != read) results->rewrite(rows, stop);  // else the file holds these rows, in this order
  stopIfAsked(stop);
  say(log, "writing the report");
  writeExperimentReport(dir, config, config_text, sets, rows, stop);
}

ExperimentReport runExperiment(const ExperimentConfig& config, const std::string& config_text, const std::string& dir,
                               const std::function<void(long, long)>& progress, const StopCheck& stop,
                               const std::function<void(const std::string&)>& log) {
  ExperimentReport report;
  std::vector<PreparedSet> sets;
  std::unique_ptr<ResultsFile> opened;
  try {
    sets = beginExperiment(config, dir, log, stop);
    if (fs::exists(resultsPath(dir))) say(log, "reading the runs already in " + resultsPath(dir));
    opened = std::make_unique<ResultsFile>(resultsPath(dir), stop);
  } catch (const Interrupted&) {
    report.interrupted = true;
    return report;
  }
  ResultsFile& results = *opened;
  report.episodes_resumed = static_cast<long>(results.done().size());
  std::vector<Unit> units;
  long total = 0;
  std::string planners;
  for (const agents::AgentConfig& agent : config.agents) {
    if (agents::isPlanner(agent)) planners += (planners.empty() ? "" : ", ") + agent.name;
  }
  if (!planners.empty()) {
    say(log, "skipping the planner agents (" + planners + "): external ROS planners run only through "
             "launch/experiment.launch");
  }
  for (int s = 0; s < static_cast<int>(sets.size()); ++s) {
    for (int p = 0; p < static_cast<int>(sets[s].set.problems.size()); ++p) {
      for (int a = 0; a < static_cast<int>(config.agents.size()); ++a) {
        if (agents::isPlanner(config.agents[a])) continue;
        Unit unit{s, p, a, {}};
        for (int run = 0; run < config.runsFor(config.agents[a]); ++run) {
          ++total;
          if (results.done().empty() ||
              results.done().count(RunKey{sets[s].name, sets[s].set.ids[p], config.agents[a].name, run}) == 0) {
            unit.runs.push_back(run);
          }
        }
        if (!unit.runs.empty()) units.push_back(std::move(unit));
      }
    }
  }
  if (report.episodes_resumed > 0) say(log, "resuming: " + std::to_string(report.episodes_resumed) + " runs already done");
  if (results.lostRuns() > 0) {
    say(log, "playing again " + std::to_string(results.lostRuns()) + " runs lost to the agent link (timeout, agent_lost)");
  }

  std::atomic<std::size_t> next_unit{0};
  std::atomic<long> done{report.episodes_resumed};
  std::mutex progress_mutex;
  std::exception_ptr failure;
  std::mutex failure_mutex;
  std::atomic<bool> failed{false};  // the other workers stop at once when one fails (a full disk, say)
  // Units are taken in canonical order and written in it: results.csv of a run that is not interrupted needs no
  // reordering when it finishes.
  OrderedAppender appender(&results);
  auto worker = [&]() {
    try {
      std::map<int, std::pair<std::unique_ptr<agents::Agent>, std::unique_ptr<EpisodeRunner>>> agents;
      for (;;) {
        if ((stop && stop()) || failed.load()) return;
        const std::size_t u = next_unit.fetch_add(1);
        if (u >= units.size()) return;
        const Unit& unit = units[u];
        auto& slot = agents[unit.agent];
        if (!slot.first) {
          slot.first = agents::makeAgent(config.agents[unit.agent]);
          slot.second = std::make_unique<EpisodeRunner>(config.agents[unit.agent], config.episode);
        }
        const PreparedSet& set = sets[unit.set];
        std::vector<EpisodeResult> rows;
        rows.reserve(unit.runs.size());
        const std::string& agent = config.agents[unit.agent].name;
        for (int run : unit.runs) {
          const std::uint64_t seed = runSeed(config.seed, set.name, set.set.ids[unit.problem], agent, run);
          const EpisodeOutcome outcome =
              slot.second->run(set.set.problems[unit.problem], set.grids[unit.problem], *slot.first, seed, false,
                               windowsOf(set, unit.problem));
          rows.push_back(episodeResult(set, unit.problem, agent, run, seed, outcome));
        }
        const long count = static_cast<long>(rows.size());
        appender.add(u, std::move(rows));
        const long now = done.fetch_add(count) + count;
        if (progress) {
          std::lock_guard<std::mutex> lock(progress_mutex);
          progress(now, total);
        }
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      failed.store(true);
    }
  };
  const int thread_count =
      config.threads > 0 ? config.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  std::vector<std::thread> threads;
  for (int t = 0; t < thread_count; ++t) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
  if (failure) {
    try {
      appender.flush();  // keep what the other workers finished
    } catch (const IoError&) {
      // the disk that failed the first write: that first error is the one to report
    }
    std::rethrow_exception(failure);
  }
  appender.flush();
  report.episodes_run = done.load() - report.episodes_resumed;
  try {
    finishExperiment(config, config_text, dir, sets, &results, stop, log);
  } catch (const Interrupted&) {
    report.interrupted = true;
  }
  return report;
}

}  // namespace simulator
}  // namespace ppp
