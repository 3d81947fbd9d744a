// finishExperiment puts results.csv in canonical order (set, PPP, agent, run as the config lists them) whatever
// order the rows were appended in, and leaves a file already in that order as it is; planner_moves.csv follows it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "ppp_core/rng.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_simulator/experiment_runner.hpp"
#include "ppp_simulator/planner_moves.hpp"
#include "ppp_simulator/results_file.hpp"
#include "small_sets.hpp"

namespace ppp {
namespace simulator {
namespace {

namespace fs = std::filesystem;

class FinishExperimentTest : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::remove_all(dir_);
    config_.sets = smallSetSpecs(20, 10);
    for (const char* type : {"random", "bumper"}) config_.agents.push_back(agents::AgentConfig{type, type, 0, 0.0});
    config_.runs = 4;
    config_.hardest = 1;
    sets_ = prepareSets(config_, dir_);
    // Every run, in canonical order, worked out by the nested loops.
    Rng rng(5);
    for (const agents::PreparedSet& set : sets_) {
      for (std::size_t p = 0; p < set.set.ids.size(); ++p) {
        for (const agents::AgentConfig& agent : config_.agents) {
          for (int run = 0; run < config_.runs; ++run) {
            EpisodeOutcome outcome;
            outcome.passed = rng.below(2) == 0;
            outcome.steps = outcome.passed ? 5 : 300;
            outcome.reason = outcome.passed ? reason::kGoalReached : reason::kBudgetExhausted;
            const std::uint64_t seed = runSeed(config_.seed, set.name, set.set.ids[p], agent.name, run);
            canonical_.push_back(agents::episodeResult(set, static_cast<int>(p), agent.name, run, seed, outcome));
          }
        }
      }
    }
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// results.csv after finishing an experiment whose file holds `rows` in this order.
  std::string finishedText(const std::vector<agents::EpisodeResult>& rows) {
    fs::remove(resultsPath(dir_));
    ResultsFile results(resultsPath(dir_));
    results.append(rows);
    finishExperiment(config_, "test", dir_, sets_, &results);
    return readTextFile(resultsPath(dir_), 1u << 24);
  }
  /// The text of results.csv holding `rows`.
  static std::string textOf(const std::vector<agents::EpisodeResult>& rows) {
    std::string text =
        "set,problem,agent,run,seed,pass,steps,bumps,path_length,optimal_length,reason,soft_failure,diagnosis,"
        "diagnosis_step,loop_period,endless_step,signature\n";
    for (const agents::EpisodeResult& r : rows) agents::appendCsvRow(r, &text);
    return text;
  }

  std::string dir_ = (fs::temp_directory_path() / "finish_experiment_test").string();
  ExperimentConfig config_;
  std::vector<agents::PreparedSet> sets_;
  std::vector<agents::EpisodeResult> canonical_;
};

TEST_F(FinishExperimentTest, RowsInCanonicalOrderStayAsTheyAre) {
  ASSERT_EQ(canonical_.size(), 2u * 4 * 2 * 4);
  EXPECT_EQ(finishedText(canonical_), textOf(canonical_));
}

TEST_F(FinishExperimentTest, BlocksOfRunsInAnyOrderAreOrdered) {
  // Blocks of one (set, PPP, agent) each, as workers append them, in reverse and in a shuffled order.
  std::vector<std::vector<agents::EpisodeResult>> blocks;
  for (std::size_t i = 0; i < canonical_.size(); i += 4) blocks.emplace_back(&canonical_[i], &canonical_[i] + 4);
  std::vector<agents::EpisodeResult> reversed;
  for (auto b = blocks.rbegin(); b != blocks.rend(); ++b) reversed.insert(reversed.end(), b->begin(), b->end());
  EXPECT_EQ(finishedText(reversed), textOf(canonical_));
  Rng rng(9);
  for (std::size_t i = blocks.size(); i > 1; --i) std::swap(blocks[i - 1], blocks[rng.below(i)]);
  std::vector<agents::EpisodeResult> shuffled;
  for (const auto& b : blocks) shuffled.insert(shuffled.end(), b.begin(), b.end());
  EXPECT_EQ(finishedText(shuffled), textOf(canonical_));
}

TEST_F(FinishExperimentTest, OverlappingStretchesAndSingleRowsAreOrdered) {
  // Even runs first, then odd ones: every stretch of rising keys overlaps the others.
  std::vector<agents::EpisodeResult> interleaved;
  for (int parity : {0, 1}) {
    for (const agents::EpisodeResult& r : canonical_) {
      if (r.run % 2 == parity) interleaved.push_back(r);
    }
  }
  EXPECT_EQ(finishedText(interleaved), textOf(canonical_));
  std::vector<agents::EpisodeResult> shuffled = canonical_;
  Rng rng(4);
  for (std::size_t i = shuffled.size(); i > 1; --i) std::swap(shuffled[i - 1], shuffled[rng.below(i)]);
  EXPECT_EQ(finishedText(shuffled), textOf(canonical_));
}

TEST_F(FinishExperimentTest, ALostRunPlayedAgainIsReplacedByItsReplay) {
  // Run 1 of the first block was lost to the agent link, then played again at the end (a resume).
  std::vector<agents::EpisodeResult> rows = canonical_;
  agents::EpisodeResult lost = rows[1];
  lost.passed = false;
  lost.reason = reason::kAgentLost;
  const agents::EpisodeResult replay = rows[1];
  rows[1] = lost;
  rows.push_back(replay);
  EXPECT_EQ(finishedText(rows), textOf(canonical_));
}

TEST_F(FinishExperimentTest, PlannerMovesFollowTheCanonicalOrderWhateverTheOrderRunsFinished) {
  // The bumper's runs carry actions (as a planner's do): appended in reverse order, with a stale line of a run
  // played again, planner_moves.csv ends with one line per run in results.csv's order.
  std::vector<agents::EpisodeResult> rows = canonical_;
  std::string expected = plannerMovesHeader() + "\n";
  for (agents::EpisodeResult& r : rows) {
    if (r.agent != "bumper") continue;
    r.actions.assign(static_cast<std::size_t>(r.steps), static_cast<Action>(1 + r.run % 4));
    expected += plannerMovesLine(r);
  }
  std::vector<agents::EpisodeResult> reversed(rows.rbegin(), rows.rend());
  agents::EpisodeResult stale = reversed.front();
  stale.actions.pop_back();  // a line shorter than the run's steps: not the run that stands
  const std::string moves = (fs::path(dir_) / kPlannerMovesFile).string();
  fs::remove(resultsPath(dir_));
  writeFileAtomically(moves, plannerMovesHeader() + "\n" + plannerMovesLine(stale));
  ResultsFile results(resultsPath(dir_));
  results.append(reversed);
  finishExperiment(config_, "test", dir_, sets_, &results);
  EXPECT_EQ(readTextFile(moves, 1u << 24), expected);
}

}  // namespace
}  // namespace simulator
}  // namespace ppp
