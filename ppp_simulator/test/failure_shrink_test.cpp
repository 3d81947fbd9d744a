// Shrinking real failures: agents' failing runs on hunted PPPs, shrunk and checked 1-minimal by brute force.
#include "ppp_simulator/failure_shrink.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ppp_core/error.hpp"
#include "ppp_core/ppp_file.hpp"
#include "ppp_generator/failure_fitness.hpp"
#include "ppp_generator/set_evolution.hpp"

namespace ppp {
namespace simulator {
namespace {

agents::AgentConfig agent(const std::string& type) { return agents::AgentConfig{type, type, 0, 0.0}; }

/// A small hunted set: PPPs evolved to make `type` fail (20 PPPs, 300 matings).
const ProblemSet& huntedSet(const std::string& type) {
  static std::map<std::string, ProblemSet> sets;
  auto found = sets.find(type);
  if (found != sets.end()) return found->second;
  generator::GeneratorOptions options;
  options.fitness = "failure";
  options.agents = {type};
  options.population = 20;
  options.matings = 300;
  options.runs_per_eval = 5;
  options.seed = 3;
  const generator::Fitness fitness = generator::fitnessFor(options, EpisodeOptions{}, 1);
  return sets.emplace(type, generator::evolveSet(options, fitness).set).first->second;
}

/// True when `judging` shows `keep` on `p` and on no PPP with one descriptor fewer or one made a cell smaller.
bool oneMinimal(const Problem& p, const FailureJudging& judging, const FailureToKeep& keep, std::string* why) {
  const auto shows = [&](const Problem& q) { return stillShows(playRuns(q, judging.agent, judging.episode, judging.seeds), keep); };
  if (!shows(p)) {
    *why = "the result does not fail so";
    return false;
  }
  for (std::size_t i = 0; i < p.obstacles.size(); ++i) {
    Problem fewer = p;
    fewer.obstacles.erase(fewer.obstacles.begin() + static_cast<std::ptrdiff_t>(i));
    if (shows(fewer)) {
      *why = "descriptor " + std::to_string(i) + " can go";
      return false;
    }
    for (const Obstacle& smaller : smallerObstacles(p.obstacles[i])) {
      if (smaller.x >= p.width || smaller.y < 0) continue;
      Problem q = p;
      q.obstacles[i] = smaller;
      if (shows(q)) {
        *why = "descriptor " + std::to_string(i) + " can be smaller";
        return false;
      }
    }
  }
  return true;
}

// The property, over every failing PPP of three hunted sets: the shrunk PPP still fails the same way on the same
// seeds, is 1-minimal, reads back from its file as written, and is what a second shrink of the same input gives.
TEST(FailureShrinkTest, HuntedFailuresShrinkToOneMinimalPppsThatStillFailTheSameWay) {
  int shrunk_count = 0;
  std::vector<double> cell_ratios;
  for (const std::string type : {"wall_follower_left", "explorer", "bumper"}) {
    const ProblemSet& set = huntedSet(type);
    for (std::size_t i = 0; i < set.problems.size(); ++i) {
      FailureJudging judging;
      judging.agent = agent(type);
      judging.seeds = {deriveSeed(5, {i}), deriveSeed(6, {i})};
      const RunsOutcome before = playRuns(set.problems[i], judging.agent, judging.episode, judging.seeds);
      if (before.failed == 0) continue;
      const ShrunkFailure s = shrinkFailure(set.problems[i], set.ids[i] + ".ppp", judging, ShrinkUnits::Descriptors);
      const std::string where = type + " " + set.ids[i];
      EXPECT_EQ(s.kept.failures, *std::max_element(before.kinds.begin(), before.kinds.end())) << where;
      std::string why;
      EXPECT_TRUE(oneMinimal(s.problem, judging, s.kept, &why)) << where << ": " << why;
      EXPECT_LE(s.cells_after, s.cells_before) << where;
      EXPECT_EQ(parsePpp(formatPpp(s.problem), "shrunk.ppp"), s.problem) << where;
      EXPECT_EQ(*findMetadata(s.problem.metadata, "shrunk_from"), set.ids[i] + ".ppp");
      EXPECT_EQ(*findMetadata(s.problem.metadata, "shrink_kind"), s.kept.kind);
      EXPECT_EQ(findMetadata(s.problem.metadata, "character.obstacles"), nullptr);  // the original's measures go
      EXPECT_EQ(*findMetadata(s.problem.metadata, "fitness"), "failure");  // the share of judged runs failing so
      EXPECT_EQ(*findMetadata(s.problem.metadata, "fitness_value"),
                formatShortest(s.after.kinds[static_cast<std::size_t>(diagnosis::kindIndex(s.kept.kind))] / 2.0))
          << where;
      if (shrunk_count % 7 == 0) {  // deterministic: the same bytes again (checked on a sample: it doubles the work)
        EXPECT_EQ(formatPpp(shrinkFailure(set.problems[i], set.ids[i] + ".ppp", judging, ShrinkUnits::Descriptors).problem),
                  formatPpp(s.problem))
            << where;
      }
      cell_ratios.push_back(static_cast<double>(s.cells_after) / std::max(1, s.cells_before));
      ++shrunk_count;
    }
  }
  EXPECT_GE(shrunk_count, 20) << "too few failing PPPs to test the property on";
  std::sort(cell_ratios.begin(), cell_ratios.end());
  // Measured: 54 shrunk, the median keeping 3 % of its obstacle cells.
  EXPECT_LE(cell_ratios[cell_ratios.size() / 2], 0.5);
}

TEST(FailureShrinkTest, APassingPppOrABadRequestIsRefused) {
  const Problem open = Problem::empty(6, 6, 2);
  FailureJudging judging;
  judging.agent = agent("explorer");
  judging.seeds = {1, 2};
  try {
    shrinkFailure(open, "open.ppp", judging, ShrinkUnits::Descriptors);
    ADD_FAILURE() << "an open map was shrunk";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "problem");
    EXPECT_EQ(e.problem(), "explorer passes open.ppp in all 2 runs judged: nothing to shrink");
  }
  judging.seeds.clear();
  EXPECT_THROW(shrinkFailure(open, "open.ppp", judging, ShrinkUnits::Descriptors), InvalidArgument);
  judging.seeds = {1};
  judging.min_rate = -0.5;
  try {
    judging.validate();
    ADD_FAILURE() << "a negative rate was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "min_rate");
  }
}

TEST(FailureShrinkTest, TheKindKeptIsTheMostCommonDiagnosisAndTiesGoToTheFirstKind) {
  RunsOutcome outcome;
  outcome.runs = 5;
  outcome.failed = 4;
  outcome.kinds[static_cast<std::size_t>(diagnosis::kindIndex(diagnosis::kConfined))] = 2;
  outcome.kinds[static_cast<std::size_t>(diagnosis::kindIndex(diagnosis::kLoop))] = 2;
  const FailureToKeep keep = failureShown(outcome, false);
  EXPECT_EQ(keep.kind, diagnosis::kLoop);  // loop comes before confined in kKinds
  EXPECT_EQ(keep.failures, 2);
  EXPECT_TRUE(stillShows(outcome, keep));
  const FailureToKeep any = failureShown(outcome, true);
  EXPECT_EQ(any.kind, "");
  EXPECT_EQ(any.failures, 4);
  outcome.failed = 3;
  EXPECT_FALSE(stillShows(outcome, any));
  outcome.valid = false;
  EXPECT_FALSE(stillShows(outcome, keep));  // an unsolvable candidate never counts
  outcome.valid = true;
  outcome.endless = 1;  // one of the two loops proven endless: the loops kept need not be
  EXPECT_FALSE(failureShown(outcome, false).endless);
  outcome.endless = 2;
  const FailureToKeep endless = failureShown(outcome, false);
  EXPECT_TRUE(endless.endless);
  outcome.endless = 1;
  EXPECT_FALSE(stillShows(outcome, endless));
}

/// A player standing in for a planner judged through ROS: every run on a PPP with an obstacle at `loop_at` is a
/// loop, proven endless when `endless_at` is an obstacle too; every other run passes.
RunsPlayer loopingPlanner(Cell loop_at, Cell endless_at) {
  return [=](const Problem& problem, const std::vector<std::uint64_t>& seeds) {
    const Grid grid = decodeGrid(problem);
    RunsOutcome outcome;
    outcome.runs = static_cast<int>(seeds.size());
    if (!grid.isObstacle(loop_at)) return outcome;
    outcome.failed = outcome.runs;
    outcome.kinds[static_cast<std::size_t>(diagnosis::kindIndex(diagnosis::kLoop))] = outcome.runs;
    if (grid.isObstacle(endless_at)) outcome.endless = outcome.runs;
    return outcome;
  };
}

TEST(FailureShrinkTest, AnEndlessLoopIsKeptEndless) {
  // Three single-cell blocks: the loop needs the one at (5, 5); it is proven endless only while the one at (8, 8)
  // stands too; (3, 3) matters for nothing. Shrinking an endless loop keeps both; a loop that was never proven
  // endless needs only (5, 5).
  Problem p = Problem::empty(10, 10, 3);
  p.goal = Cell{9, 9};
  for (const int at : {3, 5, 8}) p.obstacles.push_back(Obstacle{Shape::Block, at, at, 1, 1});
  FailureJudging judging;
  judging.agent = agent("planner");
  judging.seeds = {7, 8};
  judging.play = loopingPlanner(Cell{5, 5}, Cell{8, 8});
  const ShrunkFailure endless = shrinkFailure(p, "three.ppp", judging, ShrinkUnits::Descriptors);
  EXPECT_TRUE(endless.kept.endless);
  EXPECT_EQ(endless.kept.text(), "endless loop");
  EXPECT_EQ(endless.problem.obstacles, (std::vector<Obstacle>{p.obstacles[1], p.obstacles[2]}));
  EXPECT_EQ(*findMetadata(endless.problem.metadata, "shrink_kind"), "loop");
  EXPECT_EQ(*findMetadata(endless.problem.metadata, "shrink_endless"), "true");
  EXPECT_EQ(*findMetadata(endless.problem.metadata, "shrink_failed"), "2 of 2");
  judging.play = loopingPlanner(Cell{5, 5}, Cell{0, 9});  // (0, 9) is never an obstacle: no loop proven endless
  const ShrunkFailure loop = shrinkFailure(p, "three.ppp", judging, ShrinkUnits::Descriptors);
  EXPECT_FALSE(loop.kept.endless);
  EXPECT_EQ(loop.problem.obstacles, (std::vector<Obstacle>{p.obstacles[1]}));
  EXPECT_EQ(findMetadata(loop.problem.metadata, "shrink_endless"), nullptr);
}

}  // namespace
}  // namespace simulator
}  // namespace ppp
