// The batch protocol's messages: every field survives encode -> decode, empty batches too, and every malformed
// message is refused naming its field or answered as the protocol says.
#include "ppp_agents/protocol/batch_codec.hpp"
#include "ppp_core/diagnosis.hpp"

#include <gtest/gtest.h>

#include "ppp_core/error.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {
namespace protocol {
namespace {

/// A scan with every field set; episode `id` starts with it when `starting`.
ScanRequest scan(std::uint32_t id, int step, bool starting, bool prior_map) {
  ScanRequest s;
  s.episode = id;
  s.step = step;
  s.position = Cell{static_cast<int>(id % 3), 2};
  s.goal = Cell{3, 4};
  s.bumped = step % 2 == 1;
  s.range = 1;
  s.window = true;
  s.free_cells[0] = 0x1F2 | (id & 1);      // cells 1 and 4-8 free; cell 3 unknown
  s.obstacle_cells[0] = 0x004 | (id & 1);  // cell 2 an obstacle; cell 0 off the map (both bits) for odd ids
  if (starting) {
    EpisodeStart start{4, 5, Cell{0, 1}, Cell{3, 4}, 0x123456789abcdefULL + id, {}, id % 2 == 1 ? Connectivity::Eight : Connectivity::Four};
    if (prior_map) {
      start.prior_map.assign(20, kScanFree);
      start.prior_map[7] = kScanObstacle;
    }
    s.start = start;
  }
  return s;
}

void expectSameScan(const ScanRequest& got, const ScanRequest& sent, bool window) {
  EXPECT_EQ(got.episode, sent.episode);
  EXPECT_EQ(got.step, sent.step);
  EXPECT_EQ(got.position, sent.position);
  EXPECT_EQ(got.bumped, sent.bumped);
  EXPECT_EQ(got.range, sent.range);
  EXPECT_EQ(got.window, window);
  EXPECT_EQ(got.free_cells, window ? sent.free_cells : decltype(sent.free_cells){});
  EXPECT_EQ(got.obstacle_cells, window ? sent.obstacle_cells : decltype(sent.obstacle_cells){});
  ASSERT_EQ(got.start.has_value(), sent.start.has_value());
  if (!sent.start) return;
  EXPECT_EQ(got.goal, sent.goal);  // the goal travels with the start
  EXPECT_EQ(got.start->width, sent.start->width);
  EXPECT_EQ(got.start->height, sent.start->height);
  EXPECT_EQ(got.start->start, sent.start->start);
  EXPECT_EQ(got.start->goal, sent.start->goal);
  EXPECT_EQ(got.start->agent_seed, sent.start->agent_seed);
  EXPECT_EQ(got.start->prior_map, sent.start->prior_map);
  EXPECT_EQ(got.start->connectivity, sent.start->connectivity);
}

TEST(BatchCodecTest, TheWiresReasonConstantsAreTheCoresReasons) {
  // The string constants of the generated headers are not constexpr: compared here, beside the static_asserts of
  // the numeric ones in batch_codec.cpp.
  EXPECT_EQ(ppp_msgs::EpisodeFailure::NO_PATH, reason::kNoPath);
  EXPECT_EQ(ppp_msgs::EpisodeFailure::INVALID_PATH, reason::kInvalidPath);
  EXPECT_EQ(ppp_msgs::EpisodeFailure::INVALID_COMMAND, reason::kInvalidCommand);
  EXPECT_EQ(ppp_msgs::EpisodeFailure::PLANNER_TIMEOUT, reason::kPlannerTimeout);
  EXPECT_EQ(ppp_msgs::EpisodeFailure::PLANNER_LOST, reason::kPlannerLost);
  EXPECT_EQ(ppp_msgs::EpisodeFailure::PLANNER_ABORTED, reason::kPlannerAborted);
  for (const std::string& wire : {ppp_msgs::EpisodeFailure::NO_PATH, ppp_msgs::EpisodeFailure::INVALID_PATH,
                                  ppp_msgs::EpisodeFailure::INVALID_COMMAND,
                                  ppp_msgs::EpisodeFailure::PLANNER_TIMEOUT, ppp_msgs::EpisodeFailure::PLANNER_LOST,
                                  ppp_msgs::EpisodeFailure::PLANNER_ABORTED}) {
    ASSERT_NE(reason::agentReportedReason(wire), nullptr) << wire;
    EXPECT_EQ(reason::agentReportedReason(wire), wire);
  }
  EXPECT_EQ(reason::agentReportedReason(reason::kTimeout), nullptr);  // the simulator's verdicts, not an agent's
  EXPECT_EQ(reason::agentReportedReason(reason::kGoalReached), nullptr);
}

TEST(BatchCodecTest, ScansSurviveTheRoundTripWithEveryField) {
  const std::vector<ScanRequest> sent{scan(7, 0, true, true), scan(8, 3, false, false), scan(9, 0, true, false)};
  ppp_msgs::ScanBatch message;
  encodeScans(sent, &message);
  EXPECT_EQ(message.range, 1u);
  EXPECT_EQ(message.starts.size(), 2u);
  EXPECT_EQ(message.free_cells, (std::vector<std::uint64_t>{0x1F3, 0x1F2, 0x1F3}));  // a word per 3x3 window
  EXPECT_EQ(message.obstacle_cells, (std::vector<std::uint64_t>{5, 4, 5}));
  const std::vector<ScanRequest> got = decodeScans(message, true);
  ASSERT_EQ(got.size(), sent.size());
  for (std::size_t i = 0; i < got.size(); ++i) expectSameScan(got[i], sent[i], true);
  const auto prior = priorGrid(*got[0].start);
  ASSERT_NE(prior, nullptr);
  EXPECT_TRUE(prior->isObstacle(Cell{3, 1}));  // cell 7 of a 4-wide map
  EXPECT_EQ(prior->obstacleCount(), 1);
  EXPECT_EQ(priorMapCells(*prior), got[0].start->prior_map);
  EXPECT_EQ(priorGrid(*got[2].start), nullptr);
}

TEST(BatchCodecTest, WindowlessAndEmptyBatchesRoundTrip) {
  std::vector<ScanRequest> sent{scan(1, 0, true, false), scan(2, 5, false, false)};
  for (ScanRequest& s : sent) s.window = false;  // an agent that reads no window gets none
  ppp_msgs::ScanBatch message;
  encodeScans(sent, &message);
  EXPECT_TRUE(message.free_cells.empty() && message.obstacle_cells.empty());
  const std::vector<ScanRequest> got = decodeScans(message, false);
  for (std::size_t i = 0; i < got.size(); ++i) expectSameScan(got[i], sent[i], false);
  EXPECT_THROW(decodeScans(message, true), InvalidArgument);  // a windowed agent needs its windows

  encodeScans({}, &message);  // buffers are reused: nothing of the last batch stays
  EXPECT_TRUE(message.episodes.empty() && message.starts.empty() && message.free_cells.empty());
  EXPECT_TRUE(decodeScans(message, true).empty());
  std::string what;
  EXPECT_EQ(checkScanBatch(message, true, &what), "");
}

/// The field decodeScans names for `message`, or "no error".
std::string faultOf(const ppp_msgs::ScanBatch& message) {
  try {
    decodeScans(message, true);
  } catch (const InvalidArgument& e) {
    return e.name();
  }
  return "no error";
}

TEST(BatchCodecTest, MalformedScanBatchesAreRefusedNamingTheField) {
  ppp_msgs::ScanBatch good;
  encodeScans({scan(1, 0, true, true), scan(2, 4, false, false)}, &good);
  ASSERT_EQ(faultOf(good), "no error");
  auto broken = [&](auto change) {
    ppp_msgs::ScanBatch m = good;
    change(m);
    return faultOf(m);
  };
  EXPECT_EQ(broken([](auto& m) { m.steps.pop_back(); }), "batch");
  EXPECT_EQ(broken([](auto& m) { m.bumped.push_back(0); }), "batch");
  EXPECT_EQ(broken([](auto& m) { m.range = 0; }), "range");
  EXPECT_EQ(broken([](auto& m) { m.range = kMaxSensorRange + 1; }), "range");
  EXPECT_EQ(broken([](auto& m) { m.free_cells.pop_back(); }), "cells");
  EXPECT_EQ(broken([](auto& m) { m.obstacle_cells.push_back(0); }), "cells");
  EXPECT_EQ(broken([](auto& m) { m.free_cells[0] |= 1u << 9; }), "cells");     // a 3x3 window has no cell 9
  EXPECT_EQ(broken([](auto& m) { m.obstacle_cells[1] |= 1ull << 63; }), "cells");
  EXPECT_EQ(broken([](auto& m) { m.range = 4; }), "cells");  // 81 cells: two words per window
  EXPECT_EQ(broken([](auto& m) { m.starts[0].width = 0; }), "size");
  EXPECT_EQ(broken([](auto& m) { m.starts[0].height = kMaxGridSide + 1; }), "size");
  EXPECT_EQ(broken([](auto& m) { m.starts[0].start.x = 4; }), "start");
  EXPECT_EQ(broken([](auto& m) { m.starts[0].goal.y = 5; }), "goal");
  EXPECT_EQ(broken([](auto& m) { m.starts[0].prior_map.pop_back(); }), "prior_map");
  EXPECT_EQ(broken([](auto& m) { m.starts[0].prior_map[2] = kScanUnknown; }), "prior_map");
  EXPECT_EQ(broken([](auto& m) { m.starts[0].episode = 99; }), "starts");
  EXPECT_EQ(broken([](auto& m) { m.starts[0].connectivity = 6; }), "connectivity");
  EXPECT_EQ(broken([](auto& m) { m.starts[0].connectivity = 0; }), "no error");  // a sender without the field: 4
}

TEST(BatchCodecTest, MovesAndFailuresSurviveTheRoundTrip) {
  const std::vector<MoveReply> sent{{4, 0, 2, nullptr}, {5, 17, 0, reason::kNoPath}, {6, 3, 255, nullptr},
                                    {7, 1, 0, reason::kPlannerLost}};
  const ppp_msgs::MoveBatch message = encodeMoves("explorer", 12, sent);
  EXPECT_EQ(message.agent, "explorer");
  EXPECT_EQ(message.batch, 12u);
  ASSERT_EQ(message.failures.size(), 2u);
  const DecodedMoves got = decodeMoves(message);
  EXPECT_EQ(got.fault, "");
  EXPECT_STREQ(got.missing_reason, reason::kTimeout);
  ASSERT_EQ(got.moves.size(), sent.size());
  for (std::size_t i = 0; i < sent.size(); ++i) {
    EXPECT_EQ(got.moves[i].episode, sent[i].episode);
    EXPECT_EQ(got.moves[i].step, sent[i].step);
    EXPECT_EQ(got.moves[i].action, sent[i].action);
    EXPECT_EQ(got.moves[i].failure == nullptr, sent[i].failure == nullptr);
    if (sent[i].failure != nullptr) EXPECT_STREQ(got.moves[i].failure, sent[i].failure);
  }
  EXPECT_TRUE(decodeMoves(encodeMoves("a", 1, {})).moves.empty());
}

TEST(BatchCodecTest, MalformedMoveBatchesFailTheirEpisodesAsInvalidAction) {
  ppp_msgs::MoveBatch message = encodeMoves("a", 3, {{1, 0, 1, nullptr}, {2, 0, 1, nullptr}});
  message.actions.pop_back();
  DecodedMoves got = decodeMoves(message);
  EXPECT_TRUE(got.moves.empty());
  EXPECT_STREQ(got.missing_reason, reason::kInvalidAction);
  EXPECT_NE(got.fault.find("differ in length (2, 2, 1)"), std::string::npos) << got.fault;

  message = encodeMoves("a", 3, {{1, 0, 1, nullptr}});
  message.failures.resize(1);
  message.failures[0].episode = 1;
  message.failures[0].reason = "tired";  // not a reason an agent may give
  got = decodeMoves(message);
  ASSERT_EQ(got.moves.size(), 1u);
  EXPECT_STREQ(got.moves[0].failure, reason::kInvalidAction);
  EXPECT_NE(got.fault.find("'tired'"), std::string::npos);
  message.failures[0].reason = reason::kGoalReached;  // nor may an agent claim a pass
  EXPECT_STREQ(decodeMoves(message).moves[0].failure, reason::kInvalidAction);
}

TEST(BatchCodecTest, StatesAndANoPathsDiagnosisSurviveTheRoundTrip) {
  std::vector<MoveReply> sent(3);
  sent[0] = {1, 4, 2, nullptr, nullptr, 0xfeedULL};
  sent[1] = {2, 9, 0, reason::kNoPath, diagnosis::kMissedRoute, 0};
  sent[2] = {3, 1, 1, nullptr, nullptr, 7};
  ppp_msgs::MoveBatch message = encodeMoves("bridge", 2, sent);
  ASSERT_EQ(message.states.size(), 3u);
  DecodedMoves got = decodeMoves(message);
  EXPECT_EQ(got.fault, "");
  EXPECT_EQ(got.moves[0].state, 0xfeedULL);
  EXPECT_EQ(got.moves[2].state, 7u);
  EXPECT_STREQ(got.moves[1].diagnosis, diagnosis::kMissedRoute);
  EXPECT_EQ(got.moves[0].diagnosis, nullptr);
  // Agents that report no state send none at all.
  EXPECT_TRUE(encodeMoves("explorer", 1, {{1, 0, 2, nullptr}}).states.empty());
  // States of the wrong length are ignored, and said so.
  message.states.pop_back();
  got = decodeMoves(message);
  EXPECT_EQ(got.moves[0].state, 0u);
  EXPECT_NE(got.fault.find("2 states for 3 moves"), std::string::npos) << got.fault;
  // A diagnosis only refines no_path, and only as missed_route or no_route.
  message = encodeMoves("bridge", 2, sent);
  message.failures[0].diagnosis = "loop";
  got = decodeMoves(message);
  EXPECT_STREQ(got.moves[1].failure, reason::kNoPath);
  EXPECT_EQ(got.moves[1].diagnosis, nullptr);
  EXPECT_NE(got.fault.find("the diagnosis 'loop'"), std::string::npos) << got.fault;
  message.failures[0].reason = reason::kPlannerTimeout;
  message.failures[0].diagnosis = diagnosis::kNoRoute;
  got = decodeMoves(message);
  EXPECT_EQ(got.moves[1].diagnosis, nullptr);
  EXPECT_NE(got.fault.find("a planner_timeout failure"), std::string::npos) << got.fault;
}

}  // namespace
}  // namespace protocol
}  // namespace ppp
