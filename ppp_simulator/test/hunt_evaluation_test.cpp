// A hunt's evaluation request as the simulator node plays it: lanes per agent instance, results per candidate.

#include "ppp_generator/hunt_evaluation.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "ppp_agents/protocol/batch_codec.hpp"
#include "ppp_agents/protocol/batch_responder.hpp"
#include "ppp_generator/failure_fitness.hpp"
#include "ppp_simulator/failure_shrink.hpp"

namespace ppp {
namespace generator {
namespace {

agents::AgentConfig agent(const std::string& type, int instances = 0) {
  agents::AgentConfig c;
  c.name = type + "_agent";
  c.type = type;
  c.instances = instances;
  return c;
}

/// Three open 8x8 candidates, start top-left, goals 3, 6 and 14 moves away.
std::vector<Problem> candidates() {
  std::vector<Problem> problems;
  for (const Cell goal : {Cell{2, 1}, Cell{3, 3}, Cell{7, 7}}) {
    Problem p = Problem::empty(8, 8, 1);
    p.goal = goal;
    problems.push_back(p);
  }
  return problems;
}

/// Plays a built-in agent's lane through the batch protocol; returns its results.
std::vector<agents::EpisodeResult> play(agents::AgentLane& lane) {
  protocol::BatchResponder responder(lane.config());
  std::vector<agents::EpisodeResult> results;
  std::vector<protocol::ScanRequest> scans;
  ppp_msgs::ScanBatch message;
  for (std::uint32_t batch = 1; !lane.finished(); ++batch) {
    lane.scans(&scans);
    protocol::encodeScans(scans, &message);
    message.batch = batch;
    const protocol::DecodedMoves moves = protocol::decodeMoves(responder.answer(message));
    for (agents::EpisodeResult& r : lane.answer(moves.moves, moves.missing_reason)) results.push_back(std::move(r));
  }
  return results;
}

TEST(HuntEvaluationTest, APlannerHasALanePerInstanceSharingItsRuns) {
  // The random agent: one lane; the planner of 3 instances: three, of 4 runs each (3 candidates x 4 runs).
  HuntEvaluation evaluation(candidates(), {agent("random"), agent("planner", 3)}, EpisodeOptions{}, 4, 7, 16);
  ASSERT_EQ(evaluation.lanes().size(), 4u);
  EXPECT_EQ(evaluation.lanes()[0]->config().type, "random");
  EXPECT_EQ(evaluation.lanes()[0]->remaining(), 12);
  for (std::size_t i = 1; i < 4; ++i) {
    EXPECT_EQ(evaluation.lanes()[i]->config().name, "planner_agent");
    EXPECT_EQ(evaluation.lanes()[i]->remaining(), 4) << i;
  }
}

TEST(HuntEvaluationTest, APlannerInContinuousMotionIsJudgedOnContinuousLanesInSimulatedTime) {
  // Two instances of a planner driving continuously: two continuous lanes of 3 of the 6 runs (3 candidates x 2).
  agents::AgentConfig driven = agent("planner", 2);
  driven.motion = kMotionContinuous;
  HuntEvaluation evaluation(candidates(), {driven}, EpisodeOptions{}, 2, 7, 16);
  EXPECT_TRUE(evaluation.lanes().empty());
  ASSERT_EQ(evaluation.continuousLanes().size(), 2u);
  EXPECT_EQ(evaluation.continuousLanes()[0]->remaining(), 3);
  EXPECT_EQ(evaluation.continuousLanes()[1]->remaining(), 3);
  // On the third candidate (14 moves in the open) its budget is ceil(4 x 14 m / 0.5 m/s / 0.1 s) = 1120 control
  // periods and the optimal route at top speed 280. A run passed in 560 periods used half its budget and took
  // twice the optimum (regret 1); a failed run used all of it (regret 1120 / 280 - 1 = 3).
  agents::EpisodeResult passed;
  passed.agent = driven.name;
  passed.problem = "c2";
  passed.passed = true;
  passed.steps = 560;
  passed.optimal_length = 14;
  agents::EpisodeResult failed = passed;
  failed.passed = false;
  failed.steps = 17;  // ended early (a collision): its whole budget all the same
  evaluation.record({passed, failed});
  const PanelEvaluation e = evaluation.evaluations().at(2);
  EXPECT_DOUBLE_EQ(e.estimate.failure_rate, 0.5);
  EXPECT_DOUBLE_EQ(e.estimate.budget_used, 0.75);
  EXPECT_DOUBLE_EQ(e.estimate.regret, 2.0);
  EXPECT_EQ(e.estimate.steps, 560 + 17);  // the periods played, not the budgets charged
}

TEST(HuntEvaluationTest, EstimatesEqualTheInProcessFailureFitness) {
  // The random agent in 20 moves, 10 runs per candidate: the estimates through lanes are the in-process
  // fitness's, run for run (the same seeds), and they differ between the near and the far goal.
  EpisodeOptions episode;
  episode.budget = 20;
  const std::vector<Problem> problems = candidates();
  HuntEvaluation evaluation(problems, {agent("random")}, episode, 10, 7, 16);
  const std::vector<agents::EpisodeResult> rows = play(*evaluation.lanes()[0]);
  evaluation.record(rows);
  const std::vector<PanelEvaluation> got = evaluation.evaluations();
  ASSERT_EQ(got.size(), 3u);
  std::vector<long> steps(problems.size(), 0);  // the moves the rows took, candidate by candidate
  for (const agents::EpisodeResult& r : rows) steps.at(std::stoul(r.problem.substr(1))) += r.steps;
  FailurePanel panel;
  panel.agents = {agent("random")};
  panel.episode = episode;
  panel.runs_per_eval = 10;
  panel.seed = 7;
  panel.threads = 1;
  std::vector<Grid> grids;
  for (const Problem& p : problems) grids.push_back(decodeGrid(p));
  const std::vector<FailureEstimate> expected =
      estimateFailures(panel, {&problems[0], &problems[1], &problems[2]}, {&grids[0], &grids[1], &grids[2]});
  for (std::size_t p = 0; p < problems.size(); ++p) {
    EXPECT_EQ(got[p].episodes, 10);
    EXPECT_DOUBLE_EQ(got[p].estimate.failure_rate, expected[p].failure_rate) << p;
    EXPECT_DOUBLE_EQ(got[p].estimate.budget_used, expected[p].budget_used) << p;
    EXPECT_EQ(got[p].estimate.steps, steps[p]) << p;
    EXPECT_EQ(expected[p].steps, steps[p]) << p;
    EXPECT_EQ(got[p].failed, static_cast<int>(expected[p].failure_rate * 10 + 0.5)) << p;
  }
  EXPECT_LT(got[0].estimate.failure_rate, got[2].estimate.failure_rate);
}

TEST(HuntEvaluationTest, GivenRunSeedsEveryCandidateIsPlayedOnThemAndDiagnosedAsInProcess) {
  // A shrink's judging through ROS: the random agent in 12 moves on the seeds of four failed runs. Each
  // candidate's failures, their diagnoses and signatures are those of the same seeds played in process (playRuns).
  EpisodeOptions episode;
  episode.budget = 12;
  const std::vector<Problem> problems = candidates();
  const std::vector<std::uint64_t> seeds = {11, 12, 13, 99};
  HuntEvaluation evaluation(problems, {agent("random")}, episode, 4, 7, 16, seeds);
  evaluation.record(play(*evaluation.lanes()[0]));
  const std::vector<PanelEvaluation> got = evaluation.evaluations();
  ASSERT_EQ(got.size(), 3u);
  int diagnosed = 0;
  for (std::size_t p = 0; p < problems.size(); ++p) {
    const simulator::RunsOutcome expected = simulator::playRuns(problems[p], agent("random"), episode, seeds);
    EXPECT_EQ(got[p].episodes, 4);
    EXPECT_EQ(got[p].failed, expected.failed) << p;
    std::map<std::string, int> kinds;
    for (std::size_t k = 0; k < diagnosis::kKindCount; ++k) {
      if (expected.kinds[k] > 0) kinds[diagnosis::kKinds[k]] = expected.kinds[k];
    }
    EXPECT_EQ(got[p].diagnoses, kinds) << p;
    EXPECT_EQ(got[p].estimate.signatures, expected.signatures) << p;  // through the lanes as in process, run for run
    diagnosed += got[p].failed;
  }
  EXPECT_GT(diagnosed, 0);  // the far goal is not reached in 12 random moves every time
}

TEST(HuntEvaluationTest, RunSeedsMustBeOnePerRun) {
  try {
    HuntEvaluation evaluation(candidates(), {agent("random")}, EpisodeOptions{}, 3, 7, 16, {1, 2});
    FAIL() << "two seeds for three runs were taken";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "run_seeds");
  }
}

}  // namespace
}  // namespace generator
}  // namespace ppp
