// Continuous motion's batch protocol (ppp_msgs/SensingBatch, ppp_msgs/CommandBatch): runs played in lockstep through
// the messages, serialized as ROS sends them, give the in-process runner's rows; every field of a start survives the
// wire; every malformed message is refused naming its field or answered as the protocol says.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <ros/serialization.h>

#include "ppp_agents/continuous/continuous_lane.hpp"
#include "ppp_agents/continuous/continuous_runner.hpp"
#include "ppp_agents/protocol/continuous_codec.hpp"
#include "ppp_agents/protocol/continuous_responder.hpp"
#include "continuous_sets.hpp"
#include "ppp_core/episode_reason.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace protocol {
namespace {

using agents::AgentConfig;
using agents::ContinuousLane;
using agents::ContinuousReply;
using agents::ContinuousRequest;
using agents::EpisodeResult;
using agents::PreparedSet;

using agents::test::astar;
using agents::test::continuousOptions;
using agents::test::seedOf;

std::vector<PreparedSet> smallSets(const EpisodeOptions& options) { return agents::test::smallSets(options, 23); }

/// `message` written to bytes and read back, as roscpp sends it between processes.
template <class Message>
Message overTheWire(const Message& message) {
  const std::uint32_t size = ros::serialization::serializationLength(message);
  std::vector<std::uint8_t> bytes(size);
  ros::serialization::OStream out(bytes.data(), size);
  ros::serialization::serialize(out, message);
  Message read;
  ros::serialization::IStream in(bytes.data(), size);
  ros::serialization::deserialize(in, read);
  return read;
}

std::string csv(const EpisodeResult& row) {
  std::string line;
  agents::appendCsvRow(row, &line);
  return line;
}

TEST(ContinuousProtocolTest, LockstepThroughTheMessagesGivesTheInProcessRows) {
  for (const char* kinematics : {kKinematicsDiffDrive, kKinematicsHolonomic}) {
    const EpisodeOptions options = continuousOptions(kinematics);
    const std::vector<PreparedSet> sets = smallSets(options);
    std::map<std::string, std::string> expected;
    agents::ContinuousRunner runner(astar(), options);
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
      ContinuousResponder responder(astar());  // one for the whole lane, as in an agent node
      std::vector<ContinuousRequest> requests;
      std::vector<EpisodeResult> rows;
      std::uint32_t round = 0;
      while (!lane.finished()) {
        lane.requests(&requests);
        ppp_msgs::SensingBatch sensing;
        sensing.batch = ++round;
        encodeSensing(requests, &sensing);
        const ppp_msgs::CommandBatch commands = overTheWire(responder.answer(overTheWire(sensing)));
        EXPECT_EQ(commands.batch, round);
        const DecodedCommands decoded = decodeCommands(commands);
        EXPECT_EQ(decoded.fault, "");
        for (EpisodeResult& row : lane.answer(decoded.replies, decoded.missing_reason)) rows.push_back(row);
      }
      ASSERT_EQ(rows.size(), 12u) << kinematics << ", batch " << batch;
      for (const EpisodeResult& row : rows) {
        EXPECT_EQ(csv(row), expected[row.set + row.problem + std::to_string(row.run)])
            << kinematics << ", batch " << batch;
      }
      EXPECT_LE(responder.active(), static_cast<std::size_t>(batch));
      EXPECT_TRUE(responder.rejections().empty());
    }
  }
}

/// A start with every field set: a 270° laser of 271 beams, a holonomic robot, the prior map of `grid`.
agents::ContinuousStart fullStart(const Grid& grid) {
  EpisodeOptions options = continuousOptions(kKinematicsHolonomic);
  options.motion.laser_beams = 271;
  options.motion.laser_field_of_view = 270;
  options.motion.laser_range = 2.5;
  options.motion.resolution = 0.25;
  options.motion.max_linear_speed = 0.7;
  options.motion.max_angular_speed = 2.1;
  options.motion.max_linear_acceleration = 1.3;
  options.motion.max_angular_acceleration = 4.2;
  options.motion.control_period = 0.05;
  agents::ContinuousStart start;
  start.frame = MapFrame{grid.width(), grid.height(), 0.25};
  start.pose = Pose2D{0.125, 2.875, 0.1};
  start.goal = MapPoint{2.875, 0.125};
  start.radius = 0.075;
  start.limits = KinematicLimits::of(options.motion);
  start.beams = LaserBeams::of(options.motion);
  start.control_period = 0.05;
  start.seed = 0xfedcba9876543210ULL;
  start.prior_map = &grid;
  return start;
}

TEST(ContinuousProtocolTest, EveryFieldOfAStartSurvivesTheWire) {
  Rng rng(3);
  const Problem problem = randomProblem(rng, Problem::empty(12, 12, 6), 6);
  const Grid grid = decodeGrid(problem);
  const agents::ContinuousStart sent = fullStart(grid);
  const DecodedStart got = decodeContinuousStart(overTheWire(toStartMessage(7, sent)));
  const agents::ContinuousStart& s = got.start;
  EXPECT_EQ(s.frame.width, 12);
  EXPECT_EQ(s.frame.height, 12);
  EXPECT_EQ(s.frame.resolution, 0.25);
  EXPECT_EQ(s.pose.x, sent.pose.x);
  EXPECT_EQ(s.pose.y, sent.pose.y);
  EXPECT_EQ(s.pose.theta, sent.pose.theta);
  EXPECT_EQ(s.goal.x, sent.goal.x);
  EXPECT_EQ(s.goal.y, sent.goal.y);
  EXPECT_EQ(s.radius, sent.radius);
  EXPECT_TRUE(s.limits.holonomic);
  EXPECT_EQ(s.limits.max_linear_speed, 0.7);
  EXPECT_EQ(s.limits.max_angular_speed, 2.1);
  EXPECT_EQ(s.limits.max_linear_acceleration, 1.3);
  EXPECT_EQ(s.limits.max_angular_acceleration, 4.2);
  EXPECT_EQ(s.control_period, 0.05);
  EXPECT_EQ(s.seed, sent.seed);
  EXPECT_EQ(s.beams.count, 271);
  EXPECT_EQ(s.beams.range_max, 2.5);
  EXPECT_EQ(s.beams.cosines, sent.beams.cosines);  // the very directions, bit for bit
  EXPECT_EQ(s.beams.sines, sent.beams.sines);
  ASSERT_NE(s.prior_map, nullptr);
  EXPECT_EQ(s.prior_map->cells(), grid.cells());
  // No prior map for an agent not given one.
  agents::ContinuousStart blind = sent;
  blind.prior_map = nullptr;
  EXPECT_EQ(decodeContinuousStart(toStartMessage(7, blind)).start.prior_map, nullptr);
}

TEST(ContinuousProtocolTest, ABadStartIsRefusedNamingItsField) {
  const Grid grid = decodeGrid(Problem::empty(12, 12, 6));
  const ppp_msgs::ContinuousStart good = toStartMessage(1, fullStart(grid));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::pair<std::string, std::function<void(ppp_msgs::ContinuousStart*)>>> cases = {
      {"size", [](auto* m) { m->width = 0; }},
      {"size", [](auto* m) { m->height = 100000; m->width = 100000; }},
      {"resolution", [](auto* m) { m->resolution = 0; }},
      {"resolution", [nan](auto* m) { m->resolution = nan; }},
      {"start", [](auto* m) { m->start.x = 3.5; }},  // past the 3 m wide map
      {"start", [nan](auto* m) { m->start.theta = nan; }},
      {"goal", [](auto* m) { m->goal.y = -0.1; }},
      {"robot_radius", [](auto* m) { m->robot_radius = -0.1; }},
      {"kinematics", [](auto* m) { m->kinematics = "ackermann"; }},
      {"max_linear_speed", [](auto* m) { m->max_linear_speed = 0; }},
      {"max_angular_speed", [inf](auto* m) { m->max_angular_speed = inf; }},
      {"max_linear_acceleration", [](auto* m) { m->max_linear_acceleration = -1; }},
      {"max_angular_acceleration", [nan](auto* m) { m->max_angular_acceleration = nan; }},
      {"control_period", [](auto* m) { m->control_period = 0; }},
      {"laser_beams", [](auto* m) { m->laser_beams = 0; }},
      {"laser_angle_min", [inf](auto* m) { m->laser_angle_increment = inf; }},
      {"laser_range_max", [](auto* m) { m->laser_range_max = 0; }},
      {"prior_map", [](auto* m) { m->prior_map.pop_back(); }},
      {"prior_map", [](auto* m) { m->prior_map[3] = 50; }},
  };
  EXPECT_NO_THROW(decodeContinuousStart(good));
  for (const auto& [field, spoil] : cases) {
    ppp_msgs::ContinuousStart bad = good;
    spoil(&bad);
    try {
      decodeContinuousStart(bad);
      ADD_FAILURE() << "accepted a bad " << field;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.name(), field) << e.what();
    }
  }
}

/// A batch of three episodes of a small open map, the second starting with a bad kinematics.
ppp_msgs::SensingBatch threeEpisodes() {
  static const Grid grid = decodeGrid(Problem::empty(12, 12, 6));
  ppp_msgs::SensingBatch batch;
  batch.batch = 1;
  for (std::uint32_t id : {4u, 5u, 6u}) {
    agents::ContinuousStart start = fullStart(grid);
    start.frame.resolution = 1;
    start.pose = Pose2D{0.5, 11.5, 0};
    start.goal = MapPoint{11.5, 0.5};
    batch.starts.push_back(toStartMessage(id, start));
    batch.episodes.push_back(id);
    batch.steps.push_back(0);
    batch.x.push_back(0.5);
    batch.y.push_back(11.5);
    for (auto* array : {&batch.theta, &batch.forward, &batch.left, &batch.turn, &batch.time}) array->push_back(0);
  }
  batch.starts[1].kinematics = "tracked";
  return batch;
}

TEST(ContinuousProtocolTest, TheResponderFailsOnlyWhatIsMalformed) {
  ContinuousResponder responder(astar());
  const DecodedCommands first = decodeCommands(responder.answer(threeEpisodes()));
  ASSERT_EQ(first.replies.size(), 3u);
  EXPECT_EQ(first.replies[0].failure, nullptr);
  EXPECT_GT(first.replies[0].command.forward + std::abs(first.replies[0].command.turn), 0);  // it drives
  EXPECT_STREQ(first.replies[1].failure, reason::kInvalidCommand);  // its start named a kinematics that is none
  EXPECT_EQ(first.replies[2].failure, nullptr);
  EXPECT_EQ(responder.rejections().at("kinematics"), 1);
  EXPECT_EQ(responder.active(), 2u);

  // An episode never started, and an array one short: every episode of that batch fails.
  ppp_msgs::SensingBatch unknown = threeEpisodes();
  unknown.starts.clear();
  unknown.episodes = {4, 9};
  for (auto* array : {&unknown.x, &unknown.y, &unknown.theta, &unknown.forward, &unknown.left, &unknown.turn,
                      &unknown.time}) {
    array->resize(2);
  }
  unknown.steps = {1, 0};
  const DecodedCommands second = decodeCommands(responder.answer(unknown));
  EXPECT_EQ(second.replies[0].failure, nullptr);
  EXPECT_STREQ(second.replies[1].failure, reason::kInvalidCommand);
  EXPECT_EQ(responder.rejections().at("episode"), 1);
  EXPECT_EQ(responder.active(), 1u);  // episode 6 was absent: over

  ppp_msgs::SensingBatch short_array = threeEpisodes();
  short_array.time.pop_back();
  for (const ContinuousReply& reply : decodeCommands(responder.answer(short_array)).replies) {
    EXPECT_STREQ(reply.failure, reason::kInvalidCommand);
  }
  ppp_msgs::SensingBatch short_ranges = threeEpisodes();
  short_ranges.laser_beams = 2;
  short_ranges.ranges.assign(5, 1.0f);
  for (const ContinuousReply& reply : decodeCommands(responder.answer(short_ranges)).replies) {
    EXPECT_STREQ(reply.failure, reason::kInvalidCommand);
  }
  EXPECT_EQ(responder.rejections().at("batch"), 3);
  EXPECT_EQ(responder.rejections().at("ranges"), 3);

  AgentConfig explorer;
  explorer.name = explorer.type = "explorer";
  try {
    ContinuousResponder refused(explorer);
    ADD_FAILURE() << "an explorer was given continuous motion";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "motion");
  }
}

TEST(ContinuousProtocolTest, SensingCarriesEachEpisodesRangesInOrder) {
  std::vector<ContinuousRequest> requests(2);
  requests[0].episode = 3;
  requests[0].ranges = {1.0f, 2.0f, std::numeric_limits<float>::infinity()};
  requests[1].episode = 8;
  requests[1].step = 12;
  requests[1].pose = Pose2D{1.25, 2.5, -3.0};
  requests[1].velocity = BodyVelocity{0.4, 0.1, -1.2};
  requests[1].time = 1.2;
  requests[1].ranges = {4.0f, 5.0f, 6.0f};
  ppp_msgs::SensingBatch batch;
  encodeSensing(requests, &batch);
  const ppp_msgs::SensingBatch got = overTheWire(batch);
  std::string what;
  EXPECT_EQ(checkSensingBatch(got, &what), "") << what;
  EXPECT_EQ(got.laser_beams, 3u);
  EXPECT_EQ(got.ranges, (std::vector<float>{1, 2, std::numeric_limits<float>::infinity(), 4, 5, 6}));
  EXPECT_EQ(got.episodes, (std::vector<std::uint32_t>{3, 8}));
  EXPECT_EQ(got.steps[1], 12u);
  EXPECT_EQ(got.x[1], 1.25);
  EXPECT_EQ(got.y[1], 2.5);
  EXPECT_EQ(got.theta[1], -3.0);
  EXPECT_EQ(got.forward[1], 0.4);
  EXPECT_EQ(got.left[1], 0.1);
  EXPECT_EQ(got.turn[1], -1.2);
  EXPECT_EQ(got.time[1], 1.2);
  EXPECT_TRUE(got.starts.empty());
}

TEST(ContinuousProtocolTest, MalformedCommandsFailTheirEpisodesAsInvalidCommand) {
  ppp_msgs::CommandBatch uneven = encodeCommands("astar", 3, {{1, 0, BodyVelocity{0.1, 0, 0}, nullptr},
                                                              {2, 0, BodyVelocity{0.2, 0, 0}, nullptr}});
  uneven.turn.pop_back();
  const DecodedCommands broken = decodeCommands(uneven);
  EXPECT_TRUE(broken.replies.empty());
  EXPECT_STREQ(broken.missing_reason, reason::kInvalidCommand);
  EXPECT_NE(broken.fault, "");

  ppp_msgs::CommandBatch failures = encodeCommands("astar", 3, {{1, 0, BodyVelocity{}, reason::kPlannerTimeout},
                                                                {2, 0, BodyVelocity{}, nullptr}});
  ppp_msgs::EpisodeFailure made_up;
  made_up.episode = 2;
  made_up.reason = "bored";
  failures.failures.push_back(made_up);
  const DecodedCommands decoded = decodeCommands(overTheWire(failures));
  ASSERT_EQ(decoded.replies.size(), 2u);
  EXPECT_STREQ(decoded.replies[0].failure, reason::kPlannerTimeout);
  EXPECT_STREQ(decoded.replies[1].failure, reason::kInvalidCommand);
  EXPECT_NE(decoded.fault.find("bored"), std::string::npos);
}

TEST(ContinuousProtocolTest, ASilentAgentFailsItsRunsAsTimeoutThenGivesUp) {
  const EpisodeOptions options = continuousOptions(kKinematicsDiffDrive);
  const std::vector<PreparedSet> sets = smallSets(options);
  ContinuousLane lane(astar(), options, sets, seedOf, 1, 2);
  std::vector<ContinuousRequest> requests;
  lane.requests(&requests);
  std::vector<EpisodeResult> ended = lane.unanswered(reason::kTimeout, 2);
  EXPECT_EQ(ended.size(), 2u);  // the batch's two episodes
  EXPECT_EQ(lane.silentBatches(), 1);
  EXPECT_EQ(lane.remaining(), 4);
  lane.requests(&requests);
  ended = lane.unanswered(reason::kTimeout, 2);
  EXPECT_EQ(ended.size(), 4u);  // two silent batches in a row: every run left fails
  EXPECT_TRUE(lane.finished());
  for (const EpisodeResult& row : ended) EXPECT_EQ(row.reason, reason::kTimeout);
}

}  // namespace
}  // namespace protocol
}  // namespace ppp
