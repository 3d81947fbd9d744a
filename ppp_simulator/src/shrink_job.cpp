#include "ppp_simulator/shrink_job.hpp"

#include <filesystem>
#include <optional>
#include <ostream>

#include "ppp_core/error.hpp"
#include "ppp_core/option_yaml.hpp"
#include "ppp_core/ppp_file.hpp"
#include "ppp_core/problem_io.hpp"
#include "ppp_core/progress_meter.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_simulator/corpus.hpp"
#include "ppp_simulator/report/distinct_failures.hpp"
#include "ppp_simulator/results_file.hpp"

namespace ppp {
namespace simulator {

namespace {

namespace fs = std::filesystem;

/// What a file is shrunk over: the job's units, else descriptors for .ppp files and cells for imported maps.
ShrinkUnits unitsFor(const ShrinkJob& job, const std::string& path) {
  if (job.units == "descriptors") return ShrinkUnits::Descriptors;
  if (job.units == "cells") return ShrinkUnits::Cells;
  if (!job.units.empty()) throw InvalidArgument("by", "expected descriptors or cells, got '" + job.units + "'");
  return fileExtension(path) == ".ppp" ? ShrinkUnits::Descriptors : ShrinkUnits::Cells;
}

std::string summary(const ShrunkFailure& s, double seconds) {
  const std::string kind = s.kept.text();
  return std::to_string(s.descriptors_before) + " -> " + std::to_string(s.descriptors_after) + " descriptors, " +
         std::to_string(s.cells_before) + " -> " + std::to_string(s.cells_after) + " obstacle cells, still " +
         kind + " in " + *findMetadata(s.problem.metadata, "shrink_failed") + " runs (" +
         std::to_string(s.evaluations) + " candidates, " + formatFixed(seconds * 1000, 1) + " ms)";
}

/// Adds `shrunk` to `corpus`, if any, and says where it went; returns its file there ("" without a corpus).
std::string addToCorpus(Corpus* corpus, const Problem& shrunk, std::ostream& out) {
  if (corpus == nullptr) return "";
  const CorpusAddition addition = corpus->add(shrunk);
  out << (addition.added ? "  added to the corpus as " : "  in the corpus already, as ") << addition.file << "\n";
  return addition.file;
}

/// One PPP of a set as shrunk: its input file's name, what it kept, the seeds it was judged on and where it was
/// written.
struct ShrunkEntry {
  std::string name;
  std::string kept;
  std::vector<std::uint64_t> seeds;
  std::string file;
};

/// The set's shrunk PPPs grouped by trap (trapName(): one obstacle shape up to moves and symmetries), one line
/// each with its smallest PPP and the command that replays its first failing run.
void writeDistinctTraps(const ShrinkJob& job, const std::vector<Problem>& shrunk,
                        const std::vector<ShrunkEntry>& entries, std::ostream& out) {
  FailureGrouping grouping;
  for (std::size_t i = 0; i < shrunk.size(); ++i) {
    grouping.add(trapName(shrunk[i]), entries[i].name, decodeGrid(shrunk[i]).obstacleCount(), i);
  }
  const std::vector<DistinctFailure> traps = grouping.groups();
  out << traps.size() << " distinct trap" << (traps.size() == 1 ? "" : "s") << " (one obstacle shape each):\n";
  for (const DistinctFailure& trap : traps) {
    const ShrunkEntry& e = entries[trap.smallest];
    std::string replay;
    if (job.replay && !e.file.empty()) {
      FailureJudging judging = job.judging;
      judging.seeds = e.seeds;
      replay = job.replay(e.file, firstFailingSeed(shrunk[trap.smallest], judging));
    }
    out << distinctFailureLine(trap, "PPP", e.kept, e.name, replay) << "\n";
  }
}

/// The name of the directory `path` is (a set's name, as results.csv has it).
std::string directoryName(const fs::path& path) {
  return path.filename().empty() ? path.parent_path().filename().string() : path.filename().string();
}

int shrinkOne(const ShrinkJob& job, FailureJudging judging, const FailedRunSeeds* failing, Corpus* corpus,
              const StopCheck& stop, std::ostream& out) {
  if (failing != nullptr) {
    const std::string set = directoryName(fs::absolute(job.input).parent_path());
    const std::string id = fs::path(job.input).stem().string();
    const auto found = failing->find({set, id});
    if (found == failing->end()) {
      throw InvalidArgument("results", "no failed run (lost runs left out) of " + judging.agent.name + " on " + set +
                                             "/" + id + " in " + job.results);
    }
    judging.seeds = found->second;
  }
  const Problem problem = readProblemFile(job.input);
  const double start = steadySeconds();
  const ShrunkFailure shrunk =
      shrinkFailure(problem, fs::path(job.input).filename().string(), judging, unitsFor(job, job.input), stop);
  if (!job.output.empty()) writePppFile(shrunk.problem, job.output);
  out << judging.agent.name << " on " << job.input << ": " << summary(shrunk, steadySeconds() - start)
      << (job.output.empty() ? "" : "; written to " + job.output) << "\n";
  addToCorpus(corpus, shrunk.problem, out);
  return 0;
}

int shrinkSet(const ShrinkJob& job, FailureJudging judging, const FailedRunSeeds* failing, Corpus* corpus,
              const StopCheck& stop, std::ostream& out, std::ostream& err) {
  const std::size_t runs = judging.seeds.size();
  const ProblemSet set = generator::readProblemSetDirectory(job.input);
  const std::vector<std::string> files = generator::problemSetFiles(job.input);
  std::vector<Problem> shrunk;  // written only once every PPP is done, as a set
  std::vector<ShrunkEntry> entries;
  for (std::size_t i = 0; i < set.problems.size(); ++i) {
    const std::string name = fs::path(files[i]).filename().string();
    const double start = steadySeconds();
    if (failing != nullptr) {
      const auto found = failing->find({directoryName(job.input), set.ids[i]});
      if (found == failing->end()) {
        out << name << ": no failed run (lost runs left out) of " << judging.agent.name << " in " << job.results
            << ", kept out\n";
        continue;
      }
      judging.seeds = found->second;
    }
    try {
      ShrunkFailure s = shrinkFailure(set.problems[i], name, judging, unitsFor(job, name), stop);
      out << name << ": " << summary(s, steadySeconds() - start) << "\n" << std::flush;
      setMetadata(&s.problem.metadata, "id", set.ids[i]);  // a corpus's or an imported map's name, as the set's
      shrunk.push_back(s.problem);
      entries.push_back(ShrunkEntry{name, s.kept.text(), judging.seeds, ""});
    } catch (const InvalidArgument& e) {
      if (e.name() != "problem") throw;
      out << name << ": " << e.problem() << ", kept out\n";
    }
  }
  if (shrunk.empty()) {
    err << "ppp: " << judging.agent.name << " fails none of the " << set.problems.size() << " PPPs of " << job.input
        << (failing != nullptr ? " with a failed run in " + job.results
                               : " in the " + std::to_string(runs) + " runs judged")
        << ": nothing to shrink, nothing written\n";
    return 1;
  }
  const std::size_t count = shrunk.size();
  if (!job.output.empty()) {
    const ProblemSet derived = generator::problemSetFromProblems(shrunk, {}, job.input);
    generator::writeDerivedSetDirectory(job.output, derived);
    for (std::size_t i = 0; i < count; ++i) entries[i].file = (fs::path(job.output) / (derived.ids[i] + ".ppp")).string();
  }
  for (std::size_t i = 0; i < count; ++i) {
    const std::string file = addToCorpus(corpus, shrunk[i], out);
    if (!file.empty()) entries[i].file = file;
  }
  out << count << " of " << set.problems.size() << " PPPs shrunk"
      << (job.output.empty() ? "" : " into " + job.output) << "\n";
  writeDistinctTraps(job, shrunk, entries, out);
  return 0;
}

}  // namespace

void ShrinkJob::validate() const {
  judging.validate();
  unitsFor(*this, input);  // a bad --by is refused before any run
  if (!fs::exists(input)) throw InvalidArgument("input", "'" + input + "' does not exist");
  if (output.empty() && corpus.empty()) throw InvalidArgument("output", "required, unless a corpus is given");
  if (fs::is_directory(input) && fs::exists(output) && !(fs::is_directory(output) && fs::is_empty(output))) {
    throw InvalidArgument("output", "'" + output + "' exists and is not an empty directory");
  }
}

int runShrinkJob(const ShrinkJob& job, const StopCheck& stop, std::ostream& out, std::ostream& err) {
  job.validate();
  std::optional<FailedRunSeeds> failing;
  if (!job.results.empty()) {
    failing = failedRunSeeds(readResultsFile(job.results), job.judging.agent.name, job.results_runs);
  }
  std::optional<Corpus> corpus;
  if (!job.corpus.empty()) corpus.emplace(job.corpus);  // read before any shrink: a bad corpus costs none
  try {
    const FailedRunSeeds* seeds = failing ? &*failing : nullptr;
    Corpus* adding = corpus ? &*corpus : nullptr;
    return fs::is_directory(job.input) ? shrinkSet(job, job.judging, seeds, adding, stop, out, err)
                                       : shrinkOne(job, job.judging, seeds, adding, stop, out);
  } catch (const Interrupted&) {
    err << "ppp: interrupted; nothing written\n";
    return 130;
  } catch (const InvalidArgument& e) {
    if (e.name() != "problem") throw;
    err << "ppp: " << e.problem() << "; nothing written\n";
    return 1;
  }
}

std::vector<std::uint64_t> derivedRunSeeds(std::uint64_t seed, int runs) {
  if (runs < 1 || runs > kMaxJudgedRuns) {
    throw InvalidArgument("runs", "expected a number of runs in [1, " + std::to_string(kMaxJudgedRuns) + "], got " +
                                        std::to_string(runs));
  }
  std::vector<std::uint64_t> seeds;
  for (int run = 0; run < runs; ++run) seeds.push_back(deriveSeed(seed, {static_cast<std::uint64_t>(run)}));
  return seeds;
}

void ShrinkTask::validate() const {
  checkOptionRanges(shrinkTaskSpecs(), *this);
  for (const auto& [name, value] : {std::pair<const char*, const std::string*>{"config", &config},
                                    {"input", &input}, {"agent", &agent}}) {
    if (value->empty()) throw InvalidArgument(name, "required");
  }
  if (output.empty() && corpus.empty()) throw InvalidArgument("output", "required, unless a corpus is given");
}

const std::vector<OptionSpec<ShrinkTask>>& shrinkTaskSpecs() {
  using T = ShrinkTask;
  static const std::vector<OptionSpec<T>> specs = {
      declareOption("config", "the experiment YAML: its agents and episode rules",
                    +[](T& t) -> std::string& { return t.config; }),
      declareOption("input", "the .ppp, map_server .yaml or MovingAI .map file, or the set directory, to shrink",
                    +[](T& t) -> std::string& { return t.input; }),
      declareOption("output", "the shrunk .ppp file (a new directory for a set); '' with corpus: none",
                    +[](T& t) -> std::string& { return t.output; }),
      declareOption("corpus", "a corpus directory each shrunk PPP is added to, unless a PPP of the same obstacle shape "
                    "(moved, mirrored or rotated) is there ('': none)",
                    +[](T& t) -> std::string& { return t.corpus; }),
      declareOption("agent", "the config's agent whose failure is shrunk (planner agents included)",
                    +[](T& t) -> std::string& { return t.agent; }),
      declareOption("seed", "the failing run's seed (results.csv's seed column); with runs, the seed theirs derive from",
                    +[](T& t) -> std::uint64_t& { return t.seed; }),
      declareOption("runs", "judge this many runs seeded from seed, as ppp simulate seeds them (0: seed alone; with "
                    "results: at most this many of each PPP's failed runs, 3 when 0)",
                    +[](T& t) -> int& { return t.runs; }, Bounds{0, kMaxJudgedRuns}),
      declareOption("results", "an experiment's results.csv: judge each PPP on the seeds of the agent's failed runs "
                    "there (runs lost to the agent link left out)", +[](T& t) -> std::string& { return t.results; }),
      declareOption("min_rate", "keep only candidates on which at least this share of the runs fail so (0: the "
                    "original's share)", +[](T& t) -> double& { return t.min_rate; }, Bounds{0, 1}),
      declareOption("any_kind", "keep any failure, not only the diagnosis most of the failing runs had",
                    +[](T& t) -> bool& { return t.any_kind; }),
      declareOption("by", "what is removed: descriptors or cells (\"\": descriptors for .ppp files, cells for "
                    "imported maps)", +[](T& t) -> std::string& { return t.by; }),
  };
  return specs;
}

ShrinkJob shrinkJobOf(const ShrinkTask& task, const agents::AgentConfig& agent, const EpisodeOptions& episode,
                      RunsPlayer play) {
  ShrinkJob job;
  job.input = task.input;
  job.output = task.output;
  job.corpus = task.corpus;
  job.judging.agent = agent;
  job.judging.episode = episode;
  job.judging.play = std::move(play);
  job.judging.seeds = task.runs > 0 ? derivedRunSeeds(task.seed, task.runs) : std::vector<std::uint64_t>{task.seed};
  job.judging.any_kind = task.any_kind;
  job.judging.min_rate = task.min_rate;
  job.results = task.results;
  if (task.runs > 0) job.results_runs = task.runs;
  job.units = task.by;
  job.validate();
  return job;
}

}  // namespace simulator
}  // namespace ppp
