// A hunted set's corpus: an experiment shrinks each PPP its panel failed into the corpus, once per obstacle shape, on
// the seeds of the failed runs results.csv holds (checked against results.csv read independently, and every trap
// played again); a rerun adds nothing; a bad corpus is refused before any run; a planner's failures are shrunk
// through the rows the simulator plays, and one whose planner is gone is recorded with the reason.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "ppp_core/error.hpp"
#include "ppp_core/problem_io.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_simulator/experiment_runner.hpp"
#include "ppp_simulator/failure_shrink.hpp"
#include "ppp_simulator/hunt_corpus.hpp"
#include "ppp_simulator/results_file.hpp"

namespace ppp {
namespace simulator {
namespace {

namespace fs = std::filesystem;

const char* const kHuntYaml = R"(seed: 1
runs: 4
budget: 300
agents:
  - {name: wall_follower_left, type: wall_follower_left}
  - {name: explorer, type: explorer}
sets:
  - name: hunted
    generator: {fitness: failure, agents: [wall_follower_left], matings: 100, population: 10, seed: 3}
    corpus: corpus
)";

/// The fields of a CSV line whose quoted fields hold no quotes.
std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (const char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

/// The seeds as corpus.csv lists them ("1,2").
std::string seedText(const std::vector<std::uint64_t>& seeds) {
  std::string text;
  for (const std::uint64_t s : seeds) text += (text.empty() ? "" : ",") + std::to_string(s);
  return text;
}

class HuntCorpusTest : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::remove_all(root_);
    fs::create_directories(root_);
    writeFileAtomically(yamlPath(), kHuntYaml);
  }
  void TearDown() override { fs::remove_all(root_); }

  std::string yamlPath() const { return (root_ / "hunt.yaml").string(); }
  std::string out() const { return (root_ / "out").string(); }
  std::string corpus() const { return (root_ / "corpus").string(); }
  ExperimentConfig config() const { return loadExperimentConfig(yamlPath()); }

  /// corpus.csv's rows as field maps.
  std::vector<std::map<std::string, std::string>> corpusLog() const {
    const std::string text = readTextFile((fs::path(out()) / kCorpusLogFile).string(), 1u << 20);
    std::vector<std::vector<std::string>> rows;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) rows.push_back(csvFields(line));
    std::vector<std::map<std::string, std::string>> log;
    for (std::size_t r = 1; r < rows.size(); ++r) {
      std::map<std::string, std::string> row;
      for (std::size_t c = 0; c < rows[0].size(); ++c) row[rows[0][c]] = rows[r].at(c);
      log.push_back(row);
    }
    return log;
  }
  std::set<std::string> corpusFiles() const {
    std::set<std::string> files;
    if (!fs::exists(corpus())) return files;
    for (const auto& entry : fs::directory_iterator(corpus())) files.insert(entry.path().filename().string());
    return files;
  }

  fs::path root_ = fs::temp_directory_path() / "ppp_hunt_corpus_test";
};

TEST_F(HuntCorpusTest, EachFailedPppOfTheHuntGoesToTheCorpusShrunkOnItsFailedSeeds) {
  const ExperimentConfig c = config();
  EXPECT_EQ(c.sets[0].corpus, corpus());  // relative to the YAML's directory
  runExperiment(c, kHuntYaml, out());
  // The panel's failed runs, from results.csv: the first three seeds of each PPP, in run order.
  std::map<std::string, std::vector<std::uint64_t>> failed;
  std::map<std::string, std::map<int, std::uint64_t>> by_run;
  for (const agents::EpisodeResult& row : readResultsFile(resultsPath(out()))) {
    if (row.agent == "wall_follower_left" && !row.passed) by_run[row.problem][row.run] = row.seed;
  }
  for (const auto& [problem, runs] : by_run) {
    for (const auto& [run, seed] : runs) {
      if (failed[problem].size() < 3) failed[problem].push_back(seed);
    }
  }
  ASSERT_GE(failed.size(), 2u) << "the hunt should leave the wall follower failing several PPPs";
  const auto log = corpusLog();
  ASSERT_EQ(log.size(), failed.size());  // the explorer is not in the panel: none of its failures
  std::set<std::string> added;
  for (const auto& row : log) {
    EXPECT_EQ(row.at("set"), "hunted");
    EXPECT_EQ(row.at("agent"), "wall_follower_left");
    ASSERT_EQ(failed.count(row.at("problem")), 1u) << row.at("problem");
    EXPECT_EQ(row.at("seeds"), seedText(failed[row.at("problem")]));
    EXPECT_EQ(row.at("note"), "");
    EXPECT_LE(std::stoi(row.at("descriptors_after")), std::stoi(row.at("descriptors_before")));
    EXPECT_TRUE(fs::exists(fs::path(corpus()) / row.at("trap"))) << row.at("trap");
    if (row.at("added") == "true") EXPECT_TRUE(added.insert(row.at("trap")).second) << "added twice";
  }
  EXPECT_EQ(corpusFiles(), added);  // one file per trap added, nothing else
  // Every trap still fails the wall follower on the seeds it records.
  agents::AgentConfig wall{"wall_follower_left", "wall_follower_left"};
  for (const std::string& file : corpusFiles()) {
    const Problem trap = readProblemFile((fs::path(corpus()) / file).string());
    std::vector<std::uint64_t> seeds;
    for (const std::string& s : csvFields(*findMetadata(trap.metadata, "shrink_seeds"))) seeds.push_back(std::stoull(s));
    const RunsOutcome outcome = playRuns(trap, wall, c.episode, seeds);
    EXPECT_EQ(outcome.failed, outcome.runs) << file;
    EXPECT_GT(outcome.runs, 0) << file;
  }

  // A rerun (every run done) shrinks them again and finds each trap there: nothing added.
  const std::set<std::string> before = corpusFiles();
  runExperiment(config(), kHuntYaml, out());
  EXPECT_EQ(corpusFiles(), before);
  const auto again = corpusLog();
  ASSERT_EQ(again.size(), log.size());
  for (std::size_t i = 0; i < again.size(); ++i) {
    EXPECT_EQ(again[i].at("added"), "false");
    EXPECT_EQ(again[i].at("trap"), log[i].at("trap"));
  }
}

TEST_F(HuntCorpusTest, ABadCorpusIsRefusedBeforeAnyRun) {
  fs::create_directories(corpus());
  writeFileAtomically((fs::path(corpus()) / "set.csv").string(), "id\n");
  EXPECT_THROW(runExperiment(config(), kHuntYaml, out()), IoError);
  EXPECT_FALSE(fs::exists(out())) << "the experiment started";
  fs::remove_all(corpus());
  writeFileAtomically(corpus(), "not a directory\n");
  try {
    runExperiment(config(), kHuntYaml, out());
    FAIL() << "a corpus that is a file was accepted";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(corpus()), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(out())) << "the experiment started";
}

TEST_F(HuntCorpusTest, OnlyAHuntedSetTakesACorpusAndItChangesNoResult) {
  std::string yaml = kHuntYaml;
  const ExperimentConfig hunted = config();
  const std::string corpus_line = "    corpus: corpus\n";
  yaml.erase(yaml.find(corpus_line), corpus_line.size());
  const ExperimentConfig plain = parseExperimentConfig(yaml, yamlPath());
  EXPECT_EQ(experimentFingerprint(hunted), experimentFingerprint(plain));  // a rerun may add or drop it

  const std::string turns = "seed: 1\nagents:\n  - {name: explorer, type: explorer}\nsets:\n  - name: t\n"
                            "    generator: {fitness: turns}\n    corpus: c\n";
  try {
    parseExperimentConfig(turns, yamlPath()).validate();
    FAIL() << "a corpus on a turns set was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), yamlPath() + ": sets[0].corpus");
  }
  std::string empty = kHuntYaml;
  const std::string corpus_key = "corpus: corpus";
  empty.replace(empty.find(corpus_key), corpus_key.size(), "corpus: ''");
  EXPECT_THROW(parseExperimentConfig(empty, yamlPath()), ParseError);
}

TEST(FailedRunSeedsTest, FirstFailedRunsInRunOrderWithoutLostOnes) {
  auto row = [](const std::string& agent, int run, std::uint64_t seed, bool passed, const std::string& reason) {
    agents::EpisodeResult r;
    r.set = "s";
    r.problem = "p";
    r.agent = agent;
    r.run = run;
    r.seed = seed;
    r.passed = passed;
    r.reason = reason;
    return r;
  };
  const std::vector<agents::EpisodeResult> rows = {
      row("a", 4, 40, false, "budget_exhausted"), row("a", 1, 10, false, "timeout"),
      row("a", 3, 30, false, "collision"),        row("a", 0, 0, true, "goal_reached"),
      row("b", 2, 20, false, "collision"),        row("a", 5, 50, false, "planner_lost"),
      row("a", 6, 60, false, "no_path")};
  const FailedRunSeeds seeds = failedRunSeeds(rows, "a", 2);
  ASSERT_EQ(seeds.size(), 1u);
  EXPECT_EQ(seeds.at({"s", "p"}), (std::vector<std::uint64_t>{30, 40}));  // timeout and planner_lost left out
  EXPECT_EQ(failedRunSeeds(rows, "a", 5).at({"s", "p"}), (std::vector<std::uint64_t>{30, 40, 60}));
  EXPECT_TRUE(failedRunSeeds(rows, "c", 2).empty());
}

TEST(DistinctTrapLinesTest, OneLinePerTrapAndAgentWithItsFirstPppAndHowToPlayItAgain) {
  ExperimentConfig config;
  config.agents = {agents::AgentConfig{"bumper", "bumper"}, agents::AgentConfig{"mine", "planner"}};
  auto entry = [](const std::string& problem, const std::string& agent, const std::string& trap, int cells) {
    CorpusEntry e;
    e.set = "hunted";
    e.problem = problem;
    e.agent = agent;
    e.seeds = "5,9";
    e.failing_seed = 9;
    e.kept = agent == "mine" ? "missed_route" : "loop";
    e.trap = trap + ".ppp";
    e.trap_file = "corpus/" + e.trap;
    e.cells_after = cells;
    return e;
  };
  CorpusEntry lost = entry("ppp_003", "mine", "", 0);
  lost.trap.clear();
  lost.note = "its planner cannot be reached";
  const std::vector<CorpusEntry> entries = {entry("ppp_000", "bumper", "trap_a", 2), entry("ppp_001", "mine", "trap_b", 1),
                                            entry("ppp_002", "bumper", "trap_a", 2), lost,
                                            entry("ppp_004", "mine", "trap_a", 2)};
  const std::vector<std::string> lines = distinctTrapLines(config, entries);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "3 distinct traps in 4 shrunk failures (per agent):");  // the lost one is no trap
  EXPECT_EQ(lines[1], "  2 PPPs: trap_a.ppp (bumper, loop); smallest hunted/ppp_000, 2 obstacle cells; replay: "
                      "ppp replay corpus/trap_a.ppp --agent bumper --seed 9 -o path.png");
  EXPECT_EQ(lines[2], "  1 PPP: trap_b.ppp (mine, missed_route); smallest hunted/ppp_001, 1 obstacle cell; replay: "
                      "roslaunch launch/check.launch corpus:=corpus/trap_b.ppp agent:=mine config:=EXPERIMENT.yaml");
  EXPECT_EQ(lines[3].substr(0, 36), "  1 PPP: trap_a.ppp (mine, missed_ro");  // one trap, two agents: two failures
  EXPECT_EQ(distinctTrapLines(config, {}), std::vector<std::string>{"0 distinct traps in 0 shrunk failures (per agent):"});
}

class PlannerCorpusTest : public HuntCorpusTest {
 protected:
  void SetUp() override {
    HuntCorpusTest::SetUp();
    config_.runs = 1;
    config_.agents = {agents::AgentConfig{"mine", "planner"}};
    generator::GeneratorOptions g;
    g.fitness = "failure";
    g.agents = {"mine"};
    config_.sets = {SetSpec{"hunted", g, "", corpus()}};
    Problem walls = Problem::empty(10, 10, 10);
    walls.obstacles = {Obstacle{Shape::HorizontalBar, 2, 3, 4, 1}, Obstacle{Shape::Block, 6, 6, 2, 2},
                       Obstacle{Shape::VerticalBar, 8, 0, 3, 1}};
    ProblemSet set;
    set.problems = {walls, Problem::empty(10, 10, 10)};
    set.ids = {"ppp_000", "ppp_001"};
    sets_ = {agents::prepareSet("hunted", set, config_.episode)};
    agents::EpisodeResult failed;
    failed.set = "hunted";
    failed.problem = "ppp_000";
    failed.agent = "mine";
    failed.seed = 7;
    failed.reason = "no_path";
    rows_ = {failed};
  }
  ExperimentConfig config_;
  std::vector<agents::PreparedSet> sets_;
  std::vector<agents::EpisodeResult> rows_;
};

TEST_F(PlannerCorpusTest, APlannersFailureShrinksThroughTheRowsItsNodePlays) {
  // A planner that answers no path on any map with an obstacle: one descriptor is the least that fails it.
  std::vector<std::uint64_t> played;
  const PlannerRows planner = [&](const agents::AgentConfig&, const Problem& problem,
                                  const std::vector<std::uint64_t>& seeds) {
    std::vector<agents::EpisodeResult> rows;
    const Grid grid = decodeGrid(problem);
    bool obstacle = false;
    for (int y = 0; y < grid.height(); ++y) {
      for (int x = 0; x < grid.width(); ++x) obstacle = obstacle || !grid.isFree({x, y});
    }
    for (const std::uint64_t seed : seeds) {
      played.push_back(seed);
      agents::EpisodeResult r;
      r.seed = seed;
      r.passed = !obstacle;
      r.reason = obstacle ? "no_path" : "goal_reached";
      r.diagnosis = obstacle ? "no_route" : "";
      rows.push_back(r);
    }
    return rows;
  };
  const std::vector<CorpusEntry> entries = addHuntFailuresToCorpora(config_, sets_, rows_, planner);
  ASSERT_EQ(entries.size(), 1u);  // ppp_001 had no failed run
  EXPECT_EQ(entries[0].problem, "ppp_000");
  EXPECT_EQ(entries[0].seeds, "7");
  EXPECT_EQ(entries[0].descriptors_before, 3);
  EXPECT_EQ(entries[0].descriptors_after, 1);
  EXPECT_TRUE(entries[0].added);
  EXPECT_EQ(entries[0].failing_seed, 7u);
  EXPECT_EQ(entries[0].cells_after, 1);  // any obstacle fails it: the shrink leaves one descriptor of one cell
  EXPECT_EQ(corpusFiles(), std::set<std::string>{entries[0].trap});
  EXPECT_EQ(std::set<std::uint64_t>(played.begin(), played.end()), std::set<std::uint64_t>{7});
  EXPECT_EQ(readProblemFile((fs::path(corpus()) / entries[0].trap).string()).obstacles.size(), 1u);
}

TEST_F(PlannerCorpusTest, APlannerGoneIsRecordedWithTheReasonAndNothingAdded) {
  const PlannerRows gone = [](const agents::AgentConfig&, const Problem&, const std::vector<std::uint64_t>&)
      -> std::vector<agents::EpisodeResult> { throw AgentUnreachable("mine", "its bridge is gone"); };
  const std::vector<CorpusEntry> entries = addHuntFailuresToCorpora(config_, sets_, rows_, gone);
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_NE(entries[0].note.find("its bridge is gone"), std::string::npos) << entries[0].note;
  EXPECT_EQ(entries[0].trap, "");
  EXPECT_FALSE(fs::exists(corpus()));
  // Where planners cannot play (ppp experiment), their failures are left to a run through ROS.
  EXPECT_TRUE(addHuntFailuresToCorpora(config_, sets_, rows_, PlannerRows()).empty());
}

}  // namespace
}  // namespace simulator
}  // namespace ppp
