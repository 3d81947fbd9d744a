#include "ppp_simulator/experiment_runner.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include "ppp_core/dpa.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/octile.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_core/yaml_reader.hpp"
#include "ppp_agents/continuous/continuous_runner.hpp"
#include "ppp_simulator/canonical_order.hpp"
#include "ppp_agents/episode_runner.hpp"
#include "ppp_simulator/experiment_report.hpp"
#include "ppp_simulator/hunt_corpus.hpp"
#include "ppp_simulator/planner_moves.hpp"
#include "ppp_simulator/results_file.hpp"
#include "ppp_generator/set_evolution.hpp"
#include "ppp_generator/failure_fitness.hpp"

namespace ppp {
namespace simulator {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFingerprintFile = "experiment.yaml";
constexpr const char* kResultsFile = "results.csv";

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

}  // namespace

std::uint64_t runSeed(std::uint64_t experiment_seed, const std::string& set, const std::string& problem,
                      const std::string& agent, int run) {
  return deriveSeed(experiment_seed,
                    {nameHash(set), nameHash(problem), nameHash(agent), static_cast<std::uint64_t>(run)});
}

namespace {

/// Which runs of `config` an experiment lane plays (those not in `done`) and their seeds.
struct LaneRuns {
  agents::AgentLane::SeedFunction seed_of;
  agents::AgentLane::SkipFunction skip;
};

LaneRuns laneRuns(const agents::AgentConfig& config, const std::vector<agents::PreparedSet>& sets,
                  std::uint64_t experiment_seed, const std::set<RunKey>& done) {
  return {[&sets, experiment_seed, name = config.name](int set, int problem, int run) {
            return runSeed(experiment_seed, sets[set].name, sets[set].set.ids[problem], name, run);
          },
          [&sets, &done, name = config.name](int set, int problem, int run) {
            return done.count(RunKey{sets[set].name, sets[set].set.ids[problem], name, run}) > 0;
          }};
}

}  // namespace

agents::AgentLane experimentLane(const agents::AgentConfig& config, const EpisodeOptions& options,
                                 const std::vector<agents::PreparedSet>& sets, std::uint64_t experiment_seed, int runs,
                                 const std::set<RunKey>& done, int batch_size, agents::LaneShare share) {
  LaneRuns lane = laneRuns(config, sets, experiment_seed, done);
  return agents::AgentLane(config, options, sets, std::move(lane.seed_of), runs, batch_size, lane.skip, share);
}

agents::ContinuousLane experimentContinuousLane(const agents::AgentConfig& config, const EpisodeOptions& options,
                                                const std::vector<agents::PreparedSet>& sets,
                                                std::uint64_t experiment_seed, int runs, const std::set<RunKey>& done,
                                                int batch_size, agents::LaneShare share) {
  LaneRuns lane = laneRuns(config, sets, experiment_seed, done);
  return agents::ContinuousLane(config, options, sets, std::move(lane.seed_of), runs, batch_size, lane.skip, share);
}

void checkContinuousStarts(const ExperimentConfig& config, const std::vector<agents::PreparedSet>& sets) {
  const bool any = std::any_of(config.agents.begin(), config.agents.end(), [&](const agents::AgentConfig& agent) {
    return agents::playsContinuously(agent, config.episode);
  });
  for (const agents::PreparedSet& set : sets) {
    for (int p = 0; any && p < static_cast<int>(set.set.problems.size()); ++p) {
      agents::checkContinuousStart(set, p, config.episode);
    }
  }
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
  std::string difference;
  try {
    difference = yamlDifference(YAML::Load(stored), YAML::Load(wanted));
  } catch (const YAML::Exception&) {
    difference = "";  // not YAML: say where the texts part instead
  }
  if (difference.empty()) {
    std::size_t line = 1;
    for (std::size_t i = 0; i < std::min(stored.size(), wanted.size()) && stored[i] == wanted[i]; ++i) {
      line += stored[i] == '\n';
    }
    difference = "the text differs at line " + std::to_string(line);
  }
  throw IoError(dir, "holds a different experiment (" + fingerprint.string() + " against this configuration: " +
                         difference + "); its rows would be mixed with this one's, so use another output directory");
}

std::vector<agents::PreparedSet> prepareSets(const ExperimentConfig& config, const std::string& dir,
                                     const std::function<void(const std::string&)>& log, const StopCheck& stop) {
  std::vector<agents::PreparedSet> prepared;
  for (const SetSpec& spec : config.sets) {
    const std::string set_dir = setDirectory(spec, dir);
    if (spec.generator) {
      if (!fs::exists(fs::path(set_dir) / "set.csv")) {
        say(log, "generating set '" + spec.name + "' (" + spec.generator->fitness + ", " +
                     std::to_string(spec.generator->matings) + " matings)");
        generator::Fitness fitness;
        try {
          fitness = generator::fitnessFor(*spec.generator, config.agents, config.episode, config.threads);
        } catch (const InvalidArgument& e) {
          throw InvalidArgument("sets", "set '" + spec.name + "': " + e.what());
        }
        const generator::EvolvedSet evolved = generator::evolveSetDirectory(
            set_dir, generatorOptionsIn(config, spec, dir), fitness, {}, stop);
        say(log, "set '" + spec.name + "': " + evolved.summary);
      }
    }
    agents::PreparedSet p = agents::prepareSet(spec.name, generator::readProblemSetDirectory(set_dir), config.episode);
    p.directory = set_dir;
    prepared.push_back(std::move(p));
  }
  return prepared;
}

void openExperimentDirectory(const ExperimentConfig& config, const std::string& dir) {
  config.validate();
  checkCorpora(config);
  checkExperimentDirectory(config, dir);
  fs::create_directories(dir);
  writeFileAtomically((fs::path(dir) / kFingerprintFile).string(), experimentFingerprint(config));
}

std::vector<agents::PreparedSet> beginExperiment(const ExperimentConfig& config, const std::string& dir,
                                         const std::function<void(const std::string&)>& log, const StopCheck& stop) {
  openExperimentDirectory(config, dir);
  return prepareSets(config, dir, log, stop);
}

std::string resultsPath(const std::string& dir) { return (fs::path(dir) / kResultsFile).string(); }

void finishExperiment(const ExperimentConfig& config, const std::string& config_text, const std::string& dir,
                      const std::vector<agents::PreparedSet>& sets, ResultsFile* results, const StopCheck& stop,
                      const std::function<void(const std::string&)>& log, const PlannerRows& planner_rows) {
  stopIfAsked(stop);
  say(log, "finishing: results.csv in run order");
  std::vector<agents::EpisodeResult> rows = readResultsFile(resultsPath(dir), stop);
  const std::size_t read = rows.size();
  rows = standingRows(std::move(rows));
  const bool moved = putInCanonicalOrder(&rows, config, sets, resultsPath(dir), stop);
  stopIfAsked(stop);
  if (moved || rows.size() != read) results->rewrite(rows, stop);  // else the file holds these rows, in this order
  stopIfAsked(stop);
  const std::string moves = (fs::path(dir) / kPlannerMovesFile).string();
  if (fs::exists(moves)) {
    // In results.csv's order, the standing line of each run: the same bytes whatever the order runs finished in.
    attachPlannerMoves(moves, &rows, stop);
    writePlannerMoves(moves, rows, stop);
  }
  say(log, "writing the report");
  writeExperimentReport(dir, config, config_text, sets, rows, stop, planner_rows);
  if (hasCorpus(config)) {
    say(log, "adding the hunted sets' failures to their corpora");
    const std::string corpus_log = (fs::path(dir) / kCorpusLogFile).string();
    fs::remove(corpus_log);  // an interrupted step leaves none, not an older run's
    const std::vector<CorpusEntry> entries = addHuntFailuresToCorpora(config, sets, rows, planner_rows, stop, log);
    writeCorpusLog(corpus_log, entries);
    for (const std::string& line : distinctTrapLines(config, entries)) say(log, line);
  }
}

ExperimentReport runExperiment(const ExperimentConfig& config, const std::string& config_text, const std::string& dir,
                               const std::function<void(long, long)>& progress, const StopCheck& stop,
                               const std::function<void(const std::string&)>& log) {
  ExperimentReport report;
  std::vector<agents::PreparedSet> sets;
  std::unique_ptr<ResultsFile> opened;
  try {
    sets = beginExperiment(config, dir, log, stop);
    checkContinuousStarts(config, sets);
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
      std::map<int, std::pair<std::unique_ptr<agents::Agent>, std::unique_ptr<agents::EpisodeRunner>>> agents;
      std::map<int, std::unique_ptr<agents::ContinuousRunner>> continuous;
      for (;;) {
        if ((stop && stop()) || failed.load()) return;
        const std::size_t u = next_unit.fetch_add(1);
        if (u >= units.size()) return;
        const Unit& unit = units[u];
        const agents::AgentConfig& config_of_agent = config.agents[unit.agent];
        const agents::PreparedSet& set = sets[unit.set];
        std::vector<agents::EpisodeResult> rows;
        rows.reserve(unit.runs.size());
        const std::string& agent = config_of_agent.name;
        if (agents::playsContinuously(config_of_agent, config.episode)) {
          auto& runner = continuous[unit.agent];
          if (!runner) runner = std::make_unique<agents::ContinuousRunner>(config_of_agent, config.episode);
          for (int run : unit.runs) {
            const std::uint64_t seed = runSeed(config.seed, set.name, set.set.ids[unit.problem], agent, run);
            rows.push_back(runner->row(set, unit.problem, run, seed));
          }
        } else {
          auto& slot = agents[unit.agent];
          if (!slot.first) {
            slot.first = agents::makeAgent(config_of_agent);
            slot.second = std::make_unique<agents::EpisodeRunner>(config_of_agent, config.episode);
          }
          for (int run : unit.runs) {
            const std::uint64_t seed = runSeed(config.seed, set.name, set.set.ids[unit.problem], agent, run);
            const EpisodeOutcome outcome =
                slot.second->run(set.set.problems[unit.problem], set.grids[unit.problem], *slot.first, seed, false,
                                 agents::windowsOf(set, unit.problem));
            rows.push_back(agents::episodeResult(set, unit.problem, agent, run, seed, outcome));
          }
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
