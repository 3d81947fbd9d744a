// Continuous runs played in lockstep batches (ContinuousLane, the simulator's side of continuous motion through
// ROS) give the rows the in-process runner gives, whatever the batch size; missing, late, failed and invalid
// answers end runs with their reasons.

#include "ppp_agents/continuous/continuous_lane.hpp"

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ppp_agents/continuous/continuous_runner.hpp"
#include "continuous_sets.hpp"
#include "ppp_core/episode_reason.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace agents {
namespace {

using test::astar;
using test::continuousOptions;
using test::seedOf;

std::vector<PreparedSet> smallSets(const EpisodeOptions& options) { return test::smallSets(options, 17); }

/// Plays `lane` to the end, answering each request as a fresh continuous A* per episode would.
std::vector<EpisodeResult> playAll(ContinuousLane* lane) {
  std::map<std::uint32_t, std::unique_ptr<ContinuousAgent>> agents;
  std::vector<EpisodeResult> rows;
  std::vector<ContinuousRequest> requests;
  while (!lane->finished()) {
    lane->requests(&requests);
    std::vector<ContinuousReply> replies;
    for (const ContinuousRequest& r : requests) {
      auto& agent = agents[r.episode];
      if (r.start) {
        agent = makeContinuousAgent(astar());
        agent->start(*r.start);
      }
      const ContinuousSensing sensing{r.pose, r.velocity, r.time, &r.ranges};
      replies.push_back({r.episode, r.step, agent->command(sensing), nullptr});
    }
    for (EpisodeResult& row : lane->answer(replies, reason::kTimeout)) rows.push_back(std::move(row));
  }
  return rows;
}

std::string csv(const EpisodeResult& row) {
  std::string line;
  appendCsvRow(row, &line);
  return line;
}

TEST(ContinuousLaneTest, LockstepRowsAreTheInProcessRowsWhateverTheBatchSize) {
  const EpisodeOptions options = continuousOptions();
  const std::vector<PreparedSet> sets = smallSets(options);
  std::map<std::string, std::string> expected;  // by set, PPP and run
  ContinuousRunner runner(astar(), options);
  for (int s = 0; s < 2; ++s) {
    for (int p = 0; p < 3; ++p) {
      for (int run = 0; run < 2; ++run) {
        const EpisodeResult row = runner.row(sets[s], p, run, seedOf(s, p, run));
        EXPECT_TRUE(row.passed) << csv(row);
        expected[row.set + row.problem + std::to_string(run)] = csv(row);
      }
    }
  }
  for (const int batch : {1, 5, 64}) {
    ContinuousLane lane(astar(), options, sets, seedOf, 2, batch);
    const std::vector<EpisodeResult> rows = playAll(&lane);
    ASSERT_EQ(rows.size(), 12u) << "batch " << batch;
    for (const EpisodeResult& row : rows) {
      EXPECT_EQ(csv(row), expected[row.set + row.problem + std::to_string(row.run)]) << "batch " << batch;
    }
  }
}

TEST(ContinuousLaneTest, MissingLateFailedAndInvalidAnswersEndRunsWithTheirReasons) {
  const EpisodeOptions options = continuousOptions();
  const std::vector<PreparedSet> sets = smallSets(options);
  ContinuousLane lane(astar(), options, sets, seedOf, 1, 4);
  std::vector<ContinuousRequest> requests;
  lane.requests(&requests);
  ASSERT_EQ(requests.size(), 4u);
  EXPECT_TRUE(requests[0].start.has_value());
  EXPECT_TRUE(requests[0].ranges.empty());  // astar does not read the laser
  ASSERT_NE(requests[0].start->prior_map, nullptr);
  const std::vector<ContinuousReply> replies = {
      {requests[0].episode, requests[0].step + 1, BodyVelocity{}, nullptr},            // for another step
      {requests[1].episode, requests[1].step, BodyVelocity{std::nan(""), 0, 0}, nullptr},  // not a number
      {requests[2].episode, requests[2].step, BodyVelocity{}, reason::kPlannerTimeout},   // the agent's failure
  };  // and none for the fourth (set b's ppp_000)
  std::map<std::string, std::string> reasons;
  for (const EpisodeResult& row : lane.answer(replies, reason::kTimeout)) reasons[row.set + "/" + row.problem] = row.reason;
  EXPECT_EQ(reasons["a/ppp_000"], reason::kInvalidCommand);
  EXPECT_EQ(reasons["a/ppp_001"], reason::kInvalidCommand);
  EXPECT_EQ(reasons["a/ppp_002"], reason::kPlannerTimeout);
  EXPECT_EQ(reasons["b/ppp_000"], reason::kTimeout);
  EXPECT_EQ(reasons.size(), 4u);
  EXPECT_EQ(lane.remaining(), 2);  // set b's ppp_001 and ppp_002 still queued
  const std::vector<EpisodeResult> lost = lane.failAll(reason::kAgentLost);
  EXPECT_EQ(lost.size(), 2u);
  for (const EpisodeResult& row : lost) EXPECT_EQ(row.reason, reason::kAgentLost);
  EXPECT_TRUE(lane.finished());
}

TEST(ContinuousLaneTest, AnAgentThatMovesOnlyOnTheGridIsRefused) {
  const EpisodeOptions options = continuousOptions();
  const std::vector<PreparedSet> sets = smallSets(options);
  AgentConfig explorer;
  explorer.name = explorer.type = "explorer";
  EXPECT_THROW(ContinuousLane(explorer, options, sets, seedOf, 1, 4), InvalidArgument);
}

TEST(ContinuousLaneTest, APlannersRowsCarryItsCommandsWhichPlayEachRunAgain) {
  // A planner given the true map, answered here as the A* control would drive: its rows keep every command.
  AgentConfig driver;
  driver.name = "driver";
  driver.type = kPlannerType;
  driver.prior_map = true;
  const EpisodeOptions options = continuousOptions();
  const std::vector<PreparedSet> sets = smallSets(options);
  ContinuousLane lane(driver, options, sets, seedOf, 1, 4);
  const std::vector<EpisodeResult> rows = playAll(&lane);
  ASSERT_EQ(rows.size(), 6u);
  for (const EpisodeResult& row : rows) {
    ASSERT_EQ(static_cast<int>(row.commands.size()), row.steps) << csv(row);
    const int s = row.set == "a" ? 0 : 1;
    const int p = row.problem.back() - '0';
    const Problem& problem = sets[s].set.problems[p];
    const ContinuousOutcome again = recordedContinuousRun(problem, sets[s].grids[p], options, sets[s].moves[p],
                                                          row.seed, row.commands, row.reason, driver.name);
    EXPECT_EQ(again.steps, row.steps) << csv(row);
    EXPECT_EQ(again.reason, row.reason) << csv(row);
    EXPECT_DOUBLE_EQ(again.distance / options.motion.resolution, row.path_length) << csv(row);
    EXPECT_EQ(static_cast<int>(again.poses.size()), row.steps + 1) << csv(row);
    // Commands cut short do not play the run again: the error names the agent and the seed.
    const std::vector<BodyVelocity> cut(row.commands.begin(), row.commands.end() - 1);
    try {
      recordedContinuousRun(problem, sets[s].grids[p], options, sets[s].moves[p], row.seed, cut, row.reason,
                            driver.name);
      ADD_FAILURE() << "a cut run played again: " << csv(row);
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("driver with seed " + std::to_string(row.seed)), std::string::npos)
          << e.what();
    }
  }
  // A built-in agent's rows keep none: it plays again in process.
  ContinuousLane control(astar(), options, sets, seedOf, 1, 4);
  for (const EpisodeResult& row : playAll(&control)) EXPECT_TRUE(row.commands.empty());
}

}  // namespace
}  // namespace agents
}  // namespace ppp
