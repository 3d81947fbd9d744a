// The failure fitness: exact figures on a hand-made map, determinism, panels and whole hunts.

#include "ppp_generator/failure_fitness.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "ppp_agents/episode_runner.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/reachability.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_generator/evaluation_log.hpp"
#include "ppp_generator/set_evolution.hpp"

namespace ppp {
namespace generator {
namespace {

namespace fs = std::filesystem;

agents::AgentConfig builtIn(const std::string& type) {
  agents::AgentConfig c;
  c.name = type;
  c.type = type;
  return c;
}

/// 20x20, start (0,0), goal (19,19), a 6x6 island on the diagonal (cells 7..12): the wall followers meet it
/// first and circle it for ever (agent_faults_test); astar walks 38 moves round it.
Problem islandProblem() {
  Problem p = Problem::empty(20, 20, 1);
  p.goal = Cell{19, 19};
  Obstacle block;
  block.shape = Shape::Block;
  block.x = 7;
  block.y = 7;
  block.length = 6;
  block.height = 6;
  p.obstacles.push_back(block);
  return p;
}

TEST(FailureFitnessTest, HandWorkedFiguresOnTheIsland) {
  // wall_follower_left fails all 10 runs using the whole budget; astar passes all in 38 of 300 moves.
  // failure_rate = (1 + 0) / 2 = 0.5; budget_used = (300/300 + 38/300) / 2 = 0.56333...
  FailurePanel panel;
  panel.agents = {builtIn("wall_follower_left"), builtIn("astar")};
  panel.runs_per_eval = 10;
  const Problem problem = islandProblem();
  const Grid grid = decodeGrid(problem);
  const auto estimates = estimateFailures(panel, {&problem}, {&grid});
  ASSERT_EQ(estimates.size(), 1u);
  EXPECT_DOUBLE_EQ(estimates[0].failure_rate, 0.5);
  EXPECT_NEAR(estimates[0].budget_used, (1.0 + 38.0 / 300.0) / 2.0, 1e-12);
  EXPECT_EQ(estimates[0].steps, 10 * 300 + 10 * 38);  // the steps played: every move of both agents' runs
  int signed_runs = 0;
  for (const auto& [signature, runs] : estimates[0].signatures) signed_runs += runs;
  EXPECT_EQ(signed_runs, 10);  // the wall follower's failed runs, each signed once
  const Fitness fitness = makeFailureFitness(panel);
  const auto scores = fitness.batch({&problem}, {&grid});
  EXPECT_DOUBLE_EQ(scores[0].value, 0.5);
  EXPECT_NEAR(scores[0].score, 0.5 + 0.001 * (1.0 + 38.0 / 300.0) / 2.0, 1e-12);
  EXPECT_EQ(fitness.batch_size, kFailureBatchSize);
}

TEST(FailureFitnessTest, FailedRunsAreSignedOnlyForAnArchiveKeyedBySignatures) {
  // The wall follower fails its 10 runs on the island: a hunt whose archive reads signatures gets them, another
  // hunt's scores carry none (signing costs time no one reads); the failure rate and steps are the same.
  const Problem problem = islandProblem();
  const Grid grid = decodeGrid(problem);
  GeneratorOptions options;
  options.fitness = kFailureFitness;
  options.agents = {"wall_follower_left"};
  options.runs_per_eval = 10;
  std::vector<FitnessScore> scores;
  for (const char* archive : {kNoArchive, kMapElitesArchive, kSignatureArchive}) {
    options.archive = archive;
    scores.push_back(fitnessFor(options, {}, EpisodeOptions{}, 1).batch({&problem}, {&grid}).at(0));
    EXPECT_DOUBLE_EQ(scores.back().failure_rate, 1.0) << archive;
    EXPECT_EQ(scores.back().steps, 3000) << archive;
  }
  EXPECT_TRUE(scores[0].signatures.empty());
  EXPECT_TRUE(scores[1].signatures.empty());
  ASSERT_FALSE(scores[2].signatures.empty());
  int signed_runs = 0;
  for (const auto& [signature, runs] : scores[2].signatures) signed_runs += runs;
  EXPECT_EQ(signed_runs, 10);
}

TEST(FailureFitnessTest, TheRoundSizeIsTheBatchOfCandidatesScoredTogether) {
  // A generator's round_size becomes the fitness's batch (the genetic algorithm's matings per round); outside
  // [1, kMaxRoundSize] it is refused by name.
  GeneratorOptions options;
  options.fitness = kFailureFitness;
  options.agents = {"explorer"};
  options.round_size = 64;
  EXPECT_EQ(fitnessFor(options, {}, EpisodeOptions{}, 1).batch_size, 64);
  options.round_size = 1;
  EXPECT_EQ(fitnessFor(options, {}, EpisodeOptions{}, 1).batch_size, 1);
  for (const int bad : {0, kMaxRoundSize + 1}) {
    options.round_size = bad;
    try {
      fitnessFor(options, {}, EpisodeOptions{}, 1);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.name(), "round_size") << bad;
    }
  }
}

TEST(FailureFitnessTest, RegretHandWorkedOnTheIslandUnderBothBudgets) {
  // astar's 38 moves are the optimum (regret 0); wall_follower_left fails, using its whole budget.
  // Budget 300: its regret is (300 - 38) / 38 per run; the panel's mean (262/38 + 0) / 2 = 131/38.
  FailurePanel panel;
  panel.fitness = kRegretFitness;
  panel.agents = {builtIn("wall_follower_left"), builtIn("astar")};
  panel.runs_per_eval = 10;
  const Problem problem = islandProblem();
  const Grid grid = decodeGrid(problem);
  FailureEstimate e = estimateFailures(panel, {&problem}, {&grid})[0];
  EXPECT_NEAR(e.regret, 131.0 / 38.0, 1e-12);
  std::vector<FitnessScore> scores = makeFailureFitness(panel).batch({&problem}, {&grid});
  EXPECT_NEAR(scores[0].value, 131.0 / 38.0, 1e-12);
  EXPECT_NEAR(scores[0].score, 131.0 / 38.0 + 0.001 * (1.0 + 38.0 / 300.0) / 2.0, 1e-12);
  // budget_factor 2: each episode gets 76 moves; the wall follower's regret is (76 - 38) / 38 = 1, astar uses half
  // its budget: regret (1 + 0) / 2, budget used (76/76 + 38/76) / 2.
  panel.episode.budget_factor = 2;
  e = estimateFailures(panel, {&problem}, {&grid})[0];
  EXPECT_DOUBLE_EQ(e.regret, 0.5);
  EXPECT_DOUBLE_EQ(e.failure_rate, 0.5);
  EXPECT_DOUBLE_EQ(e.budget_used, 0.75);
  EXPECT_EQ(makeFailureFitness(panel).name, kRegretFitness);
  panel.fitness = "turns";
  EXPECT_THROW(makeFailureFitness(panel), InvalidArgument);
}

TEST(FailureFitnessTest, TalliesWorkedByHand) {
  // Agent 0: passed in 50 and failed (budget 300); agent 1: passed in 38 and in 76; optimum 38.
  PanelTally tally(2);
  tally.add(0, true, 50, 300, 38);
  tally.add(0, false, 120, 300, 38);  // a timeout after 120 moves counts the whole budget
  tally.add(1, true, 38, 300, 38);
  tally.add(1, true, 76, 300, 38);
  const FailureEstimate e = estimateOf(tally, 2, 300);
  EXPECT_DOUBLE_EQ(e.failure_rate, (0.5 + 0) / 2);
  EXPECT_NEAR(e.budget_used, ((50 + 300) / 600.0 + (38 + 76) / 600.0) / 2, 1e-12);
  EXPECT_NEAR(e.regret, ((12.0 / 38 + 262.0 / 38) / 2 + (0 + 1.0) / 2) / 2, 1e-12);
  EXPECT_DOUBLE_EQ(panelScore(kFailureFitness, e).value, e.failure_rate);
  EXPECT_DOUBLE_EQ(panelScore(kRegretFitness, e).value, e.regret);
}

TEST(FailureFitnessTest, SoftFailuresCountAsFailuresWhenARatioIsSet) {
  // The long-term explorer reaches the goal round the island on detours; which of its runs are longer than 1.2 x
  // the optimum is read off each run replayed on its own, then compared with the fitness's failure rate.
  FailurePanel panel;
  panel.agents = {builtIn("long_term_explorer")};
  panel.runs_per_eval = 10;
  panel.episode.soft_failure_ratio = 1.2;
  const Problem problem = islandProblem();
  const Grid grid = decodeGrid(problem);
  int failed = 0;
  for (int run = 0; run < panel.runs_per_eval; ++run) {
    const std::uint64_t seed = failureRunSeed(panel.seed, grid.hash(), "long_term_explorer", run);
    const EpisodeOutcome outcome = agents::recordEpisode(problem, grid, panel.agents[0], EpisodeOptions{}, seed);
    failed += !outcome.passed || pathLength(outcome) > 1.2 * 38 ? 1 : 0;
  }
  EXPECT_GT(failed, 0) << "no detour longer than 1.2 x: the test shows nothing";
  EXPECT_DOUBLE_EQ(estimateFailures(panel, {&problem}, {&grid})[0].failure_rate, failed / 10.0);
  panel.episode.soft_failure_ratio = 0;
  EXPECT_LT(estimateFailures(panel, {&problem}, {&grid})[0].failure_rate, failed / 10.0);
}

TEST(FailureFitnessTest, APppIsJudgedTheSameWhateverItsBatchPositionOrThreads) {
  Rng rng(11);
  std::vector<Problem> problems;
  std::vector<Grid> grids;
  while (problems.size() < 6) {
    Problem p = Problem::empty(12, 12, 6);
    p.goal = Cell{11, 11};
    for (int i = 0; i < 6; ++i) p.obstacles.push_back(randomObstacle(rng, 12, 12, {}));
    Grid g = decodeGrid(p);
    if (!isReachable(g, p.start, p.goal)) continue;
    problems.push_back(p);
    grids.push_back(g);
  }
  FailurePanel panel;
  panel.agents = {builtIn("random"), builtIn("explorer"), builtIn("bumper")};
  panel.runs_per_eval = 7;
  panel.threads = 1;
  std::vector<const Problem*> forward, backward;
  std::vector<const Grid*> forward_grids, backward_grids;
  for (std::size_t i = 0; i < problems.size(); ++i) {
    forward.push_back(&problems[i]);
    forward_grids.push_back(&grids[i]);
    backward.insert(backward.begin(), &problems[i]);
    backward_grids.insert(backward_grids.begin(), &grids[i]);
  }
  const auto one_thread = estimateFailures(panel, forward, forward_grids);
  panel.threads = 2;
  const auto two_threads = estimateFailures(panel, forward, forward_grids);
  const auto reversed = estimateFailures(panel, backward, backward_grids);
  bool some_failure = false;
  for (std::size_t i = 0; i < problems.size(); ++i) {
    EXPECT_EQ(one_thread[i].failure_rate, two_threads[i].failure_rate);
    EXPECT_EQ(one_thread[i].budget_used, two_threads[i].budget_used);
    EXPECT_EQ(one_thread[i].failure_rate, reversed[problems.size() - 1 - i].failure_rate);
    some_failure |= one_thread[i].failure_rate > 0;
  }
  EXPECT_TRUE(some_failure) << "the panel passed everything: the test shows nothing";
  panel.seed = 2;  // another generator seed draws other runs
  const auto other = estimateFailures(panel, forward, forward_grids);
  bool differs = false;
  for (std::size_t i = 0; i < problems.size(); ++i) differs |= other[i].budget_used != one_thread[i].budget_used;
  EXPECT_TRUE(differs);
}

std::string errorOf(const std::vector<std::string>& names, const std::vector<agents::AgentConfig>& available) {
  try {
    resolvePanel(names, available);
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "no error";
}

TEST(FailureFitnessTest, PanelsResolveByNameAndRefuseWhatCannotRunInProcess) {
  agents::AgentConfig memory = builtIn("explorer");
  memory.name = "explorer_memory_5x5";
  memory.memory_window = 5;
  agents::AgentConfig planner = builtIn("planner");
  planner.name = "mine";
  const std::vector<agents::AgentConfig> available{builtIn("astar"), memory, planner};
  const auto panel = resolvePanel({"explorer_memory_5x5", "astar"}, available);
  ASSERT_EQ(panel.size(), 2u);
  EXPECT_EQ(panel[0].memory_window, 5);
  EXPECT_EQ(resolvePanel({"bumper"}, {}).at(0).type, "bumper");  // no file: built-in type names
  EXPECT_EQ(errorOf({"explorer"}, available),
            "agents: unknown agent 'explorer'; valid: astar, explorer_memory_5x5, mine");
  EXPECT_EQ(errorOf({"wall_folower"}, {}).rfind("agents: unknown agent 'wall_folower'; with no agents file", 0), 0u);
  EXPECT_EQ(errorOf({}, available), "agents: empty panel: a panel fitness (failure, regret) needs at least one agent name");
  EXPECT_EQ(errorOf({"mine"}, available).rfind("agents: 'mine' is a ROS planner agent; in process", 0), 0u);
}

/// Every file of a directory, by name.
std::map<std::string, std::string> filesOf(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    files[entry.path().filename().string()] = readTextFile(entry.path().string(), 1u << 24);
  }
  const auto log = files.find(generator::kEvaluationLogFile);  // its wall times differ from run to run
  if (log != files.end()) log->second = generator::withoutSeconds(log->second);
  return files;
}

TEST(FailureFitnessTest, AHuntIsByteIdenticalForASeedAndFindsFailures) {
  const fs::path root = fs::temp_directory_path() / "failure_fitness_test";
  fs::remove_all(root);
  for (const std::string& archive : {generator::kNoArchive, generator::kMapElitesArchive}) {
    GeneratorOptions o;
    o.fitness = kFailureFitness;
    o.agents = {"wall_follower_left", "bumper"};
    o.runs_per_eval = 4;
    o.population = 16;
    o.matings = 300;
    o.seed = 9;
    o.archive = archive;
    const generator::EvolvedSet a =
        generator::evolveSetDirectory((root / (archive + "_a")).string(), o, fitnessFor(o, {}, EpisodeOptions{}, 2));
    const generator::EvolvedSet b =
        generator::evolveSetDirectory((root / (archive + "_b")).string(), o, fitnessFor(o, {}, EpisodeOptions{}, 1));
    EXPECT_EQ(filesOf(root / (archive + "_a")), filesOf(root / (archive + "_b"))) << archive;
    EXPECT_EQ(fs::exists(root / (archive + "_a") / "archive.svg"), archive == generator::kMapElitesArchive);
    double mean = 0;
    for (double v : a.set.fitness_values) mean += v / static_cast<double>(a.set.fitness_values.size());
    std::printf("[ measured ] %s hunt: mean failure rate %.3f, diversity %.3f\n", archive.c_str(), mean,
                a.set.diversity);
    EXPECT_GT(mean, 0.5) << archive;  // measured: above 0.8 for both
  }
  fs::remove_all(root);
}

}  // namespace
}  // namespace generator
}  // namespace ppp
