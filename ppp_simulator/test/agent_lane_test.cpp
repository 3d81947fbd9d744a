#include "ppp_simulator/experiment_runner.hpp"

#include <gtest/gtest.h>

#include <functional>

#include <algorithm>
#include <filesystem>

#include "ppp_agents/protocol/batch_responder.hpp"
#include "ppp_core/error.hpp"
#include "small_sets.hpp"

namespace ppp {
namespace simulator {
namespace {

namespace fs = std::filesystem;

/// Two small evolved sets, prepared once for every test.
const std::vector<agents::PreparedSet>& smallSets() {
  static const std::vector<agents::PreparedSet> sets = [] {
    ExperimentConfig config;
    config.sets = smallSetSpecs(50, 12);
    const std::string dir = (fs::temp_directory_path() / "agent_lane_test_sets").string();
    fs::remove_all(dir);
    return prepareSets(config, dir);
  }();
  return sets;
}

agents::AgentConfig config(const std::string& type, int memory = 0, double noise = 0.0) {
  return agents::AgentConfig{type + "_" + std::to_string(memory), type, memory, noise};
}

/// Plays a lane to the end through the real protocol: each batch is encoded as the simulator node sends it,
/// answered by the agent node's BatchResponder and the answer decoded as the simulator node reads it.
std::vector<agents::EpisodeResult> playLane(agents::AgentLane& lane) {
  protocol::BatchResponder responder(lane.config());
  std::vector<agents::EpisodeResult> results;
  std::vector<protocol::ScanRequest> scans;
  ppp_msgs::ScanBatch message;
  for (std::uint32_t batch = 1; !lane.finished(); ++batch) {
    lane.scans(&scans);
    protocol::encodeScans(scans, &message);
    message.batch = batch;
    EXPECT_EQ(message.free_cells.empty(), !agents::readsScanWindow(lane.config()) || scans.empty());
    const protocol::DecodedMoves moves = protocol::decodeMoves(responder.answer(message));
    EXPECT_EQ(moves.fault, "");
    for (agents::EpisodeResult& r : lane.answer(moves.moves, moves.missing_reason)) results.push_back(std::move(r));
  }
  EXPECT_EQ(responder.rejections().size(), 0u);
  return results;
}

/// The in-process runner's results for the same runs.
std::vector<agents::EpisodeResult> inProcess(const agents::AgentConfig& c, int runs,
                                     const EpisodeOptions& options = EpisodeOptions{}) {
  std::vector<agents::EpisodeResult> results;
  agents::EpisodeRunner runner(c, options);
  auto agent = agents::makeAgent(c);
  for (const agents::PreparedSet& set : smallSets()) {
    for (std::size_t p = 0; p < set.set.problems.size(); ++p) {
      for (int run = 0; run < runs; ++run) {
        const std::uint64_t seed = runSeed(5, set.name, set.set.ids[p], c.name, run);
        const auto o = runner.run(set.set.problems[p], set.grids[p], *agent, seed);
        results.push_back(agents::episodeResult(set, static_cast<int>(p), c.name, run, seed, o));
      }
    }
  }
  return results;
}

void sortRows(std::vector<agents::EpisodeResult>* rows) {
  std::sort(rows->begin(), rows->end(), [](const agents::EpisodeResult& a, const agents::EpisodeResult& b) {
    return std::tie(a.set, a.problem, a.run) < std::tie(b.set, b.problem, b.run);
  });
}

TEST(AgentLaneTest, BatchedPlayEqualsTheInProcessRunnerForEveryAgentAndBatchSize) {
  for (const agents::AgentConfig& c : {config("astar"), config("random"), config("explorer", 5), config("explorer", 0, 0.1),
                                       config("long_term_explorer"), config("wall_follower_right"),
                                       config("decision_bumper")}) {
    auto expected = inProcess(c, 6);
    sortRows(&expected);
    for (int batch : {1, 7, 100}) {
      agents::AgentLane lane = experimentLane(c, EpisodeOptions{}, smallSets(), 5, 6, {}, batch);
      auto got = playLane(lane);
      sortRows(&got);
      ASSERT_EQ(got.size(), expected.size());
      for (std::size_t i = 0; i < got.size(); ++i) {
        EXPECT_EQ(agents::toCsvFields(got[i]), agents::toCsvFields(expected[i])) << c.name << " batch " << batch << " row " << i;
      }
    }
  }
}

TEST(AgentLaneTest, BatchedPlayEqualsTheInProcessRunnerUnderConnectivityEight) {
  EpisodeOptions octile;
  octile.connectivity = Connectivity::Eight;
  for (const agents::AgentConfig& c : {config("astar"), config("random")}) {
    auto expected = inProcess(c, 4, octile);
    sortRows(&expected);
    agents::AgentLane lane = experimentLane(c, octile, smallSets(), 5, 4, {}, 9);
    auto got = playLane(lane);
    sortRows(&got);
    ASSERT_EQ(got.size(), expected.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(agents::toCsvFields(got[i]), agents::toCsvFields(expected[i])) << c.name << " row " << i;
    }
  }
  // Sets prepared for connectivity 8 carry octile optimal lengths, which astar's lane meets exactly.
  std::vector<agents::PreparedSet> octile_sets;
  for (const agents::PreparedSet& set : smallSets()) octile_sets.push_back(agents::prepareSet(set.name, set.set, octile));
  agents::AgentLane lane = experimentLane(config("astar"), octile, octile_sets, 5, 1, {}, 9);
  int shorter = 0;
  for (const agents::EpisodeResult& r : playLane(lane)) {
    EXPECT_TRUE(r.passed);
    EXPECT_NEAR(r.path_length, r.optimal_length, 1e-9) << r.set << " " << r.problem;
    const agents::PreparedSet& four = smallSets()[r.set == smallSets()[0].name ? 0 : 1];
    const auto p = std::find(four.set.ids.begin(), four.set.ids.end(), r.problem) - four.set.ids.begin();
    shorter += r.optimal_length < four.optimal[static_cast<std::size_t>(p)] ? 1 : 0;
  }
  EXPECT_GT(shorter, 0);  // diagonals shorten some routes
}

TEST(AgentLaneTest, FaultsFailOnlyTheirEpisodes) {
  agents::AgentLane lane = experimentLane(config("random"), EpisodeOptions{}, smallSets(), 5, 2, {}, 4);
  std::vector<protocol::ScanRequest> scans;
  lane.scans(&scans);
  ASSERT_EQ(scans.size(), 4u);
  // Episode 0 answered well, 1 for the wrong step, 2 with an unknown action, 3 not at all.
  const std::vector<protocol::MoveReply> moves{{scans[0].episode, 0, 0}, {scans[1].episode, 5, 0}, {scans[2].episode, 0, 9},
                                     {999, 0, 1}};
  const auto ended = lane.answer(moves, reason::kTimeout);
  ASSERT_EQ(ended.size(), 3u);
  EXPECT_EQ(ended[0].reason, reason::kInvalidAction);
  EXPECT_EQ(ended[1].reason, reason::kInvalidAction);
  EXPECT_EQ(ended[2].reason, reason::kTimeout);
  EXPECT_EQ(lane.remaining(), 2 * 4 * 2 - 3);
  const auto lost = lane.failAll(reason::kAgentLost);
  EXPECT_EQ(lost.size(), static_cast<std::size_t>(2 * 4 * 2 - 3));
  for (const auto& r : lost) EXPECT_EQ(r.reason, reason::kAgentLost);
  EXPECT_TRUE(lane.finished());
}

TEST(AgentLaneTest, APlannerDrivingARobotWithABodyIntoAWallEndsItsRunAsACollision) {
  // A corridor three cells high (rows 1-3) narrowing to two from x = 4: a disc of radius 1 stands at (1, 2) or
  // (2, 2) only. Its north move would put the disc over the top wall.
  Problem corridor = Problem::empty(9, 5, 3);
  corridor.start = Cell{1, 2};
  corridor.goal = Cell{2, 2};
  corridor.obstacles = {Obstacle{Shape::HorizontalBar, 0, 0, 9, 1}, Obstacle{Shape::HorizontalBar, 0, 4, 9, 1},
                        Obstacle{Shape::HorizontalBar, 4, 3, 5, 1}};
  EpisodeOptions body;
  body.robot_radius = 1;
  ProblemSet set;
  set.ids = {"corridor"};
  set.problems = {corridor};
  const std::vector<agents::PreparedSet> sets = {agents::prepareSet("corridor", set, body)};
  const auto endOfNorth = [&](const agents::AgentConfig& agent) {
    agents::AgentLane lane(agent, body, sets, [](int, int, int) { return 1u; }, 1, 1);
    std::vector<protocol::ScanRequest> scans;
    lane.scans(&scans);
    const auto ended = lane.answer({{scans[0].episode, 0, static_cast<int>(Action::North)}}, reason::kTimeout);
    return ended.empty() ? std::string("still running") : ended[0].reason;
  };
  agents::AgentConfig planner{"mine", agents::kPlannerType, 0, 0.0};
  EXPECT_EQ(endOfNorth(planner), reason::kCollision);
  EXPECT_EQ(endOfNorth(config("bumper")), "still running");  // a built-in agent bumps and goes on, as a point would
}

// A planner's run cannot be replayed, so its result carries the actions it took (for planner_moves.csv); a
// built-in agent's carries none (it is replayed from its seed).
TEST(AgentLaneTest, APlannersResultsCarryTheirActions) {
  ProblemSet set;
  set.ids = {"open"};
  set.problems = {Problem::empty(3, 3, 1)};
  const std::vector<agents::PreparedSet> sets = {agents::prepareSet("open", set, EpisodeOptions{})};
  const auto play = [&](const agents::AgentConfig& agent, const std::vector<Action>& moves) {
    agents::AgentLane lane(agent, EpisodeOptions{}, sets, [](int, int, int) { return 1u; }, 1, 1);
    std::vector<protocol::ScanRequest> scans;
    std::vector<agents::EpisodeResult> ended;
    for (const Action a : moves) {
      lane.scans(&scans);
      ended = lane.answer({{scans[0].episode, scans[0].step, static_cast<int>(a)}}, reason::kTimeout);
    }
    if (ended.empty()) ended = lane.failAll(reason::kNoPath);  // a planner that gave up mid-run
    return ended.at(0);
  };
  const std::vector<Action> to_goal = {Action::East, Action::Stay, Action::North, Action::East, Action::South,
                                       Action::South};
  const agents::AgentConfig planner{"mine", agents::kPlannerType, 0, 0.0};
  const agents::EpisodeResult passed = play(planner, to_goal);
  EXPECT_TRUE(passed.passed);
  EXPECT_EQ(passed.actions, to_goal);  // the stay and the bump against the top edge included
  const agents::EpisodeResult stopped = play(planner, {Action::East, Action::East});
  EXPECT_EQ(stopped.reason, reason::kNoPath);
  EXPECT_EQ(stopped.actions, (std::vector<Action>{Action::East, Action::East}));
  EXPECT_TRUE(play(config("bumper"), to_goal).actions.empty());
}

// A planner shuttling east and west on an open 5 x 5 map until its budget of 20 moves runs out: a loop of period
// 2 from step 1. Its states prove it endless from the first step whose state recurs two steps later; a noisy
// sensor (the next scan is no function of the state), a built-in agent or states that never recur prove nothing.
TEST(AgentLaneTest, APlannersRecurringStatesProveItsLoopEndless) {
  ProblemSet set;
  set.ids = {"open"};
  set.problems = {Problem::empty(5, 5, 1)};
  EpisodeOptions options;
  options.budget = 20;
  const std::vector<agents::PreparedSet> sets = {agents::prepareSet("open", set, options)};
  const auto play = [&](const agents::AgentConfig& agent, const std::function<std::uint64_t(int)>& state) {
    agents::AgentLane lane(agent, options, sets, [](int, int, int) { return 1u; }, 1, 1);
    std::vector<protocol::ScanRequest> scans;
    std::vector<agents::EpisodeResult> ended;
    for (int step = 0; ended.empty(); ++step) {
      lane.scans(&scans);
      protocol::MoveReply move{scans[0].episode, scans[0].step, static_cast<int>(step % 2 ? Action::West : Action::East)};
      move.state = state(step);
      ended = lane.answer({move}, reason::kTimeout);
    }
    return ended.at(0);
  };
  const agents::AgentConfig planner{"mine", agents::kPlannerType, 0, 0.0};
  // States 100, 101, ... up to step 4 (the robot still learning), then alternating 7, 8.
  const auto settling = [](int step) { return step < 5 ? 100u + step : 7u + step % 2; };
  const agents::EpisodeResult loop = play(planner, settling);
  EXPECT_EQ(loop.reason, reason::kBudgetExhausted);
  EXPECT_EQ(loop.diagnosis, diagnosis::kLoop);
  EXPECT_EQ(loop.loop_period, 2);
  EXPECT_EQ(loop.diagnosis_step, 0);  // (0,0), (1,0), (0,0), ... from the start
  EXPECT_EQ(loop.endless_step, 5);
  EXPECT_EQ(play(planner, [](int step) { return 100u + step; }).endless_step, -1);
  EXPECT_EQ(play(planner, [](int) { return 0u; }).endless_step, -1);  // no states given
  EXPECT_EQ(play(agents::AgentConfig{"noisy", agents::kPlannerType, 0, 0.1}, settling).endless_step, -1);
  const agents::EpisodeResult built_in = play(config("bumper"), settling);
  EXPECT_EQ(built_in.diagnosis, diagnosis::kLoop);
  EXPECT_EQ(built_in.endless_step, -1);
}

// A planner's no_path comes with the bridge's diagnosis of it; without one it is reported.
TEST(AgentLaneTest, APlannersNoPathKeepsTheDiagnosisItCameWith) {
  ProblemSet set;
  set.ids = {"open"};
  set.problems = {Problem::empty(5, 5, 1)};
  const std::vector<agents::PreparedSet> sets = {agents::prepareSet("open", set, EpisodeOptions{})};
  const auto give_up = [&](const char* kind) {
    agents::AgentLane lane({"mine", agents::kPlannerType, 0, 0.0}, EpisodeOptions{}, sets, [](int, int, int) { return 1u; },
                           1, 1);
    std::vector<protocol::ScanRequest> scans;
    lane.scans(&scans);
    protocol::MoveReply move{scans[0].episode, scans[0].step, 0, reason::kNoPath, kind};
    return lane.answer({move}, reason::kTimeout).at(0);
  };
  EXPECT_EQ(give_up(diagnosis::kMissedRoute).diagnosis, diagnosis::kMissedRoute);
  EXPECT_EQ(give_up(diagnosis::kNoRoute).diagnosis, diagnosis::kNoRoute);
  EXPECT_EQ(give_up(nullptr).diagnosis, diagnosis::kReported);
}

TEST(AgentLaneTest, ASilentAgentIsGivenUpAfterSomeUnansweredBatches) {
  agents::AgentLane lane = experimentLane(config("random"), EpisodeOptions{}, smallSets(), 5, 2, {}, 4);
  std::vector<protocol::ScanRequest> scans;
  lane.scans(&scans);
  EXPECT_EQ(lane.unanswered(reason::kTimeout, 2).size(), 4u);  // only the batch's episodes
  EXPECT_FALSE(lane.finished());
  lane.scans(&scans);
  const auto ended = lane.unanswered(reason::kTimeout, 2);     // second in a row: everything left
  EXPECT_EQ(ended.size(), static_cast<std::size_t>(2 * 4 * 2 - 4));
  for (const auto& r : ended) EXPECT_EQ(r.reason, reason::kTimeout);
  EXPECT_TRUE(lane.finished());
}

TEST(AgentLaneTest, InstancesShareTheRunsAndTogetherPlayThemAsOneLane) {
  // Three lanes, each every third run of the lane's order, with one run done: disjoint shares of 8 or 7 runs
  // whose results together are the one lane's, row for row.
  const agents::AgentConfig c = config("explorer", 5);
  const std::set<RunKey> done{{"turns", smallSets()[0].set.ids[1], c.name, 0}};  // position 3: instance 0's
  agents::AgentLane whole = experimentLane(c, EpisodeOptions{}, smallSets(), 5, 3, done, 4);
  auto expected = playLane(whole);
  sortRows(&expected);
  ASSERT_EQ(expected.size(), static_cast<std::size_t>(2 * 4 * 3 - 1));
  std::vector<agents::EpisodeResult> together;
  for (int instance = 0; instance < 3; ++instance) {
    agents::AgentLane share = experimentLane(c, EpisodeOptions{}, smallSets(), 5, 3, done, 4, {instance, 3});
    EXPECT_EQ(share.remaining(), instance == 0 ? 7 : 8) << instance;
    for (agents::EpisodeResult& r : playLane(share)) together.push_back(std::move(r));
  }
  sortRows(&together);
  ASSERT_EQ(together.size(), expected.size());
  for (std::size_t i = 0; i < together.size(); ++i) {
    EXPECT_EQ(agents::toCsvFields(together[i]), agents::toCsvFields(expected[i])) << "row " << i;
  }
  EXPECT_THROW(experimentLane(c, EpisodeOptions{}, smallSets(), 5, 3, {}, 4, {3, 3}), InvalidArgument);
  EXPECT_THROW(experimentLane(c, EpisodeOptions{}, smallSets(), 5, 3, {}, 4, {0, 0}), InvalidArgument);
}

TEST(AgentLaneTest, DoneRunsAreSkippedAndBadBatchSizeRefused) {
  std::set<RunKey> done{{"turns", smallSets()[0].set.ids[0], "random_0", 0}};
  agents::AgentLane lane = experimentLane(config("random"), EpisodeOptions{}, smallSets(), 5, 2, done, 3);
  EXPECT_EQ(lane.remaining(), 2 * 4 * 2 - 1);
  EXPECT_THROW(experimentLane(config("random"), EpisodeOptions{}, smallSets(), 5, 2, {}, 0), InvalidArgument);
}

}  // namespace
}  // namespace simulator
}  // namespace ppp
