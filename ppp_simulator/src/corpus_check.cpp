#include "ppp_simulator/corpus_check.hpp"

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>

#include "ppp_core/error.hpp"
#include "ppp_core/option_yaml.hpp"
#include "ppp_core/problem_io.hpp"
#include "ppp_core/progress_meter.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_simulator/report/distinct_failures.hpp"
#include "ppp_simulator/shrink_job.hpp"

namespace ppp {
namespace simulator {

namespace {

namespace fs = std::filesystem;

/// The seeds `problem` (read from `file`) records as failing ones (meta shrink_seeds), or none.
/// @throws ParseError naming the file and the key for a malformed list.
std::vector<std::uint64_t> recordedSeeds(const Problem& problem, const std::string& file) {
  const std::string* text = findMetadata(problem.metadata, "shrink_seeds");
  if (text == nullptr) return {};
  std::vector<std::uint64_t> seeds;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = std::min(text->find(',', begin), text->size());
    std::uint64_t seed = 0;
    const char* first = text->data() + begin;
    const char* last = text->data() + comma;
    const auto [end, error] = std::from_chars(first, last, seed);
    if (first == last || error != std::errc() || end != last) {
      throw ParseError(file, 0, "meta shrink_seeds",
                       "expected run seeds separated by commas (as ppp shrink writes them), got '" + *text + "'");
    }
    seeds.push_back(seed);
    if (comma == text->size()) return seeds;
    begin = comma + 1;
  }
}

/// Makes the directory of `path` if need be. @throws IoError naming `path` when a file cannot be written there.
void checkWritable(const std::string& path) {
  std::error_code error;
  if (fs::is_directory(path, error)) throw IoError(path, "is a directory; expected the JUnit XML file to write");
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty() && !fs::create_directories(parent, error) && error) {
    throw IoError(path, "cannot be written: its directory cannot be made: " + error.message());
  }
  const std::string probe = path + ".write-check";
  std::ofstream file(probe);
  if (!file) throw IoError(path, std::string("cannot be written: ") + std::strerror(errno));
  file.close();
  std::remove(probe.c_str());
}

/// "2 of 3 runs failed: loop (seed 5), stuck (seed 9)".
std::string failureSummary(const CaseVerdict& v) {
  std::string text = std::to_string(v.failed.size()) + " of " + std::to_string(v.runs) + " runs failed: ";
  for (std::size_t i = 0; i < v.failed.size(); ++i) {
    text += (i > 0 ? ", " : "") + v.diagnoses[i] + " (seed " + std::to_string(v.failed[i]) + ")";
  }
  return text;
}

/// The diagnosis of the one run `outcome` holds.
std::string diagnosisOf(const RunsOutcome& outcome) {
  for (int kind = 0; kind < diagnosis::kKindCount; ++kind) {
    if (outcome.kinds[static_cast<std::size_t>(kind)] > 0) return diagnosis::kKinds[kind];
  }
  return "failed";
}

/// A failed run of a check: its PPP, its seed and its diagnosis.
struct FailedRun {
  const CorpusCase* problem;
  std::uint64_t seed;
  std::string diagnosis;
};

/// The check's failed runs grouped by failure signature, one line each with the smallest PPP and its replay.
void writeDistinctFailures(const CheckJob& job, const FailureGrouping& grouping, const std::vector<FailedRun>& runs,
                           std::ostream& out) {
  const std::vector<DistinctFailure> kinds = grouping.groups();
  out << kinds.size() << " distinct failure" << (kinds.size() == 1 ? "" : "s") << " of " << job.task.agent
      << " by failure signature (docs/reference/signatures.md):\n";
  for (const DistinctFailure& kind : kinds) {
    const FailedRun& run = runs[kind.smallest];
    out << distinctFailureLine(kind, "run", run.diagnosis, run.problem->name, job.replay(*run.problem, run.seed))
        << "\n";
  }
}

}  // namespace

std::vector<CorpusCase> readCorpusCases(const std::string& corpus, std::uint64_t seed, int runs) {
  const std::vector<std::uint64_t> derived = derivedRunSeeds(seed, runs);
  std::vector<CorpusCase> cases;
  std::error_code error;
  std::vector<std::string> files;
  if (fs::is_directory(corpus, error)) {
    files = generator::problemSetFiles(corpus);
  } else if (fs::exists(corpus, error)) {
    files = {corpus};
  } else {
    throw IoError(corpus, "does not exist; expected a directory of PPP files or one PPP file");
  }
  // PPPs of any size: a corpus, unlike a set, has no diversity to measure.
  const std::vector<std::string> names = generator::problemNames(files, corpus);
  for (std::size_t i = 0; i < files.size(); ++i) {
    cases.push_back(CorpusCase{names[i], files[i], readProblemFile(files[i]), {}, false});
  }
  for (CorpusCase& c : cases) {
    c.seeds = recordedSeeds(c.problem, c.file);
    c.recorded = !c.seeds.empty();
    if (!c.recorded) c.seeds = derived;
  }
  return cases;
}

int runCheck(const CheckJob& job, const StopCheck& stop, std::ostream& out) {
  const std::vector<CorpusCase> cases = readCorpusCases(job.task.corpus, job.task.seed, job.task.runs);
  for (const CorpusCase& c : cases) {
    if (!solvableForRobot(c.problem, job.episode)) {
      throw InvalidArgument("corpus", c.file + ": the robot cannot play it: its goal is out of reach" +
                                          (job.episode.robot_radius > 0
                                               ? " for a robot of radius " + formatShortest(job.episode.robot_radius)
                                               : std::string()));
    }
  }
  if (!job.task.junit.empty()) checkWritable(job.task.junit);
  std::vector<CaseVerdict> verdicts;
  std::vector<std::string> failing;
  FailureGrouping grouping;
  std::vector<FailedRun> failed_runs;
  for (const CorpusCase& c : cases) {
    CaseVerdict verdict;
    const int obstacle_cells = decodeGrid(c.problem).obstacleCount();
    const double start = steadySeconds();
    for (const std::uint64_t seed : c.seeds) {
      if (stop && stop()) {
        out << "interrupted; nothing written\n";
        return 130;
      }
      const RunsOutcome outcome = job.play(c.problem, {seed});
      ++verdict.runs;
      if (outcome.failed == 0) continue;
      verdict.failed.push_back(seed);
      verdict.diagnoses.push_back(diagnosisOf(outcome));
      const std::string signature = outcome.signatures.empty() ? verdict.diagnoses.back() : outcome.signatures.begin()->first;
      grouping.add(signature, c.name, obstacle_cells, failed_runs.size());
      failed_runs.push_back(FailedRun{&c, seed, verdict.diagnoses.back()});
    }
    verdict.seconds = steadySeconds() - start;
    if (verdict.passed()) {
      out << "pass " << c.name << ": " << verdict.runs << " of " << verdict.runs << " runs passed\n";
    } else {
      out << "FAIL " << c.name << ": " << failureSummary(verdict) << "; replay: " << job.replay(c, verdict.failed[0])
          << "\n";
      failing.push_back(c.name);
    }
    out << std::flush;
    verdicts.push_back(std::move(verdict));
  }
  if (!failed_runs.empty()) writeDistinctFailures(job, grouping, failed_runs, out);
  if (!job.task.junit.empty()) {
    const fs::path corpus(job.task.corpus);
    const std::string suite = (corpus.filename().empty() ? corpus.parent_path() : corpus).filename().string();
    writeFileAtomically(job.task.junit, checkJunitXml(suite, job.task.agent, cases, verdicts, job.replay));
  }
  out << job.task.agent << (failing.empty() ? " passes all " : " fails " + std::to_string(failing.size()) + " of ")
      << cases.size() << " PPPs of " << job.task.corpus << (failing.empty() ? "" : ": " + joinNames(failing))
      << (job.task.junit.empty() ? "" : "; JUnit XML in " + job.task.junit) << "\n";
  return failing.empty() ? 0 : 1;
}

std::string checkJunitXml(const std::string& suite, const std::string& agent, const std::vector<CorpusCase>& cases,
                          const std::vector<CaseVerdict>& verdicts,
                          const std::function<std::string(const CorpusCase&, std::uint64_t)>& replay) {
  std::size_t failures = 0;
  double seconds = 0;
  for (const CaseVerdict& v : verdicts) {
    failures += v.passed() ? 0 : 1;
    seconds += v.seconds;
  }
  const std::string counts = " tests=\"" + std::to_string(cases.size()) + "\" failures=\"" + std::to_string(failures) +
                             "\" errors=\"0\" time=\"" + formatFixed(seconds, 3) + "\"";
  std::ostringstream xml;
  // One testsuite as the root, which CI systems and catkin_test_results read (a testsuites root with the same
  // counts is summed twice by the latter).
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<testsuite name=\"" << escapeMarkup(suite) << "\"" << counts << " skipped=\"0\">\n";
  for (std::size_t i = 0; i < cases.size() && i < verdicts.size(); ++i) {
    const CorpusCase& c = cases[i];
    const CaseVerdict& v = verdicts[i];
    xml << "  <testcase classname=\"ppp_check." << escapeMarkup(agent) << "\" name=\"" << escapeMarkup(c.name)
        << "\" file=\"" << escapeMarkup(c.file) << "\" time=\"" << formatFixed(v.seconds, 3) << "\"";
    if (v.passed()) {
      xml << "/>\n";
      continue;
    }
    xml << ">\n    <failure type=\"" << escapeMarkup(v.diagnoses[0]) << "\" message=\""
        << escapeMarkup(agent + " fails " + c.name + ": " + failureSummary(v)) << "\">";
    for (std::size_t k = 0; k < v.failed.size(); ++k) {
      xml << escapeMarkup("seed " + std::to_string(v.failed[k]) + ": " + v.diagnoses[k] +
                          "; replay: " + replay(c, v.failed[k]) + "\n");
    }
    xml << "</failure>\n  </testcase>\n";
  }
  xml << "</testsuite>\n";
  return xml.str();
}

std::string checkLaunchCommand(const std::string& corpus, const std::string& agent, const std::string& config) {
  return "roslaunch launch/check.launch corpus:=" + shellWord(corpus) + " agent:=" + shellWord(agent) +
         " config:=" + shellWord(config);
}

void CheckTask::validate() const {
  checkOptionRanges(checkTaskSpecs(), *this);
  for (const auto& [name, value] : {std::pair<const char*, const std::string*>{"config", &config},
                                    {"corpus", &corpus}, {"agent", &agent}}) {
    if (value->empty()) throw InvalidArgument(name, "required");
  }
}

const std::vector<OptionSpec<CheckTask>>& checkTaskSpecs() {
  using T = CheckTask;
  static const std::vector<OptionSpec<T>> specs = {
      declareOption("config", "the experiment YAML: its agents and episode rules",
                    +[](T& t) -> std::string& { return t.config; }),
      declareOption("corpus", "the corpus: a directory of PPP files (.ppp, map_server .yaml, MovingAI .map), or one "
                    "PPP file", +[](T& t) -> std::string& { return t.corpus; }),
      declareOption("agent", "the config's agent checked (planner agents included)",
                    +[](T& t) -> std::string& { return t.agent; }),
      declareOption("seed", "the seed the runs of a PPP without recorded seeds (meta shrink_seeds) derive from, as "
                    "ppp simulate derives them", +[](T& t) -> std::uint64_t& { return t.seed; }),
      declareOption("runs", "runs of a PPP without recorded seeds",
                    +[](T& t) -> int& { return t.runs; }, Bounds{1, kMaxJudgedRuns}),
      declareOption("junit", "the JUnit XML file to write: one test case per PPP ('': none)",
                    +[](T& t) -> std::string& { return t.junit; }),
  };
  return specs;
}

}  // namespace simulator
}  // namespace ppp
