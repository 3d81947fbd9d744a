// Wiring of agent_node and faulty_agent_node: topics under the node's name, one MoveBatch per ScanBatch with the
// batch number and agent name, the prior map reaching astar, rejected scans, the faulty modes, bad parameters.
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <condition_variable>
#include <cstdio>
#include <deque>
#include <mutex>
#include <optional>
#include <string>

#include "agent_node_parameters.hpp"
#include "agent_option_cases.hpp"
#include "ppp_agents/protocol/batch_responder.hpp"
#include "ppp_msgs/node_parameters.h"
#include "ppp_core/sensor.hpp"
#include "ppp_core/window_mask.hpp"
#include "ppp_msgs/MoveBatch.h"
#include "ppp_msgs/ScanBatch.h"
#include "scan_batch_builder.hpp"

namespace ppp {
namespace agents {
namespace {

/// The simulator's side of the conversation with one agent node: /NAME/scans out, /NAME/moves in.
class Conversation {
 public:
  explicit Conversation(const std::string& name) {
    ros::NodeHandle nh;
    scans_ = nh.advertise<ppp_msgs::ScanBatch>("/" + name + "/scans", 10);
    moves_ = nh.subscribe("/" + name + "/moves", 10, &Conversation::onMoves, this);
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(30.0);
    while (ros::ok() && ros::WallTime::now() < deadline &&
           (scans_.getNumSubscribers() == 0 || moves_.getNumPublishers() == 0)) {
      ros::WallDuration(0.02).sleep();  // a connection count has no event to wait on
    }
  }
  /// True when the node is connected both ways.
  bool connected() const { return scans_.getNumSubscribers() > 0 && moves_.getNumPublishers() > 0; }
  /// Sends a batch and returns the answer, if one comes within `timeout` seconds.
  std::optional<ppp_msgs::MoveBatch> exchange(const ppp_msgs::ScanBatch& batch, double timeout = 10.0) {
    std::unique_lock<std::mutex> lock(mutex_);
    received_.clear();
    scans_.publish(batch);
    if (!arrived_.wait_for(lock, std::chrono::duration<double>(timeout), [&] { return !received_.empty(); })) {
      return std::nullopt;
    }
    return received_.front();
  }

 private:
  void onMoves(const ppp_msgs::MoveBatch::ConstPtr& moves) {
    std::lock_guard<std::mutex> lock(mutex_);
    received_.push_back(*moves);
    arrived_.notify_one();
  }

  ros::Publisher scans_;
  ros::Subscriber moves_;
  std::mutex mutex_;
  std::condition_variable arrived_;
  std::deque<ppp_msgs::MoveBatch> received_;
};

/// Step 0 of an episode on a 2x2 map whose top-right cell is an obstacle: start top-left, goal bottom-right.
/// Window values follow that map (range 1).
test::TestScan cornerScan(std::uint32_t episode, bool prior_map) {
  test::TestScan s;
  s.episode = episode;
  s.step = 0;
  s.position = Cell{0, 0};
  const std::int8_t o = kScanOutOfBounds;
  const std::int8_t cells[] = {o, o, o, o, kScanFree, kScanObstacle, o, kScanFree, kScanFree};
  s.window = true;
  packWindow(cells, 1, s.free_cells.data(), s.obstacle_cells.data());
  protocol::EpisodeStart start;
  start.width = 2;
  start.height = 2;
  start.start = Cell{0, 0};
  start.goal = Cell{1, 1};
  start.agent_seed = 3;
  if (prior_map) start.prior_map = {kScanFree, kScanObstacle, kScanFree, kScanFree};
  s.start = start;
  return s;
}

/// `scan` one step later, without its EpisodeStart.
test::TestScan next(test::TestScan scan) {
  ++scan.step;
  scan.start.reset();
  return scan;
}

ppp_msgs::ScanBatch batchOf(std::uint32_t number, const std::vector<test::TestScan>& scans) {
  ppp_msgs::ScanBatch batch = test::packBatch(number, 1, scans);
  batch.header.stamp = ros::Time::now();
  return batch;
}

TEST(AgentNodeTest, AnswersEachBatchUnderItsNameAndRejectsMalformedScans) {
  Conversation agent("explorer_noise_0_1");
  ASSERT_TRUE(agent.connected()) << "no agent node on /explorer_noise_0_1/{scans,moves}";
  test::TestScan off_grid = cornerScan(2, false);
  off_grid.position = Cell{5, 0};
  const auto moves = agent.exchange(batchOf(17, {cornerScan(1, false), off_grid, cornerScan(3, false)}));
  ASSERT_TRUE(moves) << "no answer";
  EXPECT_EQ(moves->agent, "explorer_noise_0.1");
  EXPECT_EQ(moves->batch, 17u);
  EXPECT_FALSE(moves->header.stamp.isZero());
  const std::vector<std::uint32_t> episodes{1, 2, 3}, steps{0, 0, 0};
  EXPECT_EQ(moves->episodes, episodes);
  EXPECT_EQ(moves->steps, steps);
  ASSERT_EQ(moves->actions.size(), 3u);
  EXPECT_TRUE(isAction(moves->actions[0]));
  EXPECT_EQ(moves->actions[1], protocol::kRejectedAction);
  EXPECT_TRUE(isAction(moves->actions[2]));

  const auto again = agent.exchange(batchOf(18, {next(cornerScan(1, false))}));
  ASSERT_TRUE(again) << "the node stopped answering after a malformed scan";
  ASSERT_EQ(again->actions.size(), 1u);
  EXPECT_EQ(again->batch, 18u);
  EXPECT_EQ(again->steps[0], 1u);
  EXPECT_TRUE(isAction(again->actions[0]));
}

TEST(AgentNodeTest, AstarPlansOnThePriorMapAsANodeAndAsANodelet) {
  for (const char* node : {"astar", "astar_nodelet"}) {
    Conversation agent(node);
    ASSERT_TRUE(agent.connected()) << node;
    const auto moves = agent.exchange(batchOf(1, {cornerScan(5, true), cornerScan(6, false)}));
    ASSERT_TRUE(moves) << node;
    ASSERT_EQ(moves->actions.size(), 2u) << node;
    EXPECT_EQ(moves->agent, "astar") << node;
    EXPECT_EQ(moves->actions[0], static_cast<std::uint8_t>(Action::South)) << node;  // east is the obstacle
    EXPECT_EQ(moves->actions[1], protocol::kRejectedAction) << node;                  // astar without its map
  }
}

TEST(FaultyAgentNodeTest, SilentGarbageAndStopAfter) {
  Conversation silent("silent");
  Conversation garbage("garbage");
  Conversation stop_after("stop_after");
  ASSERT_TRUE(silent.connected() && garbage.connected() && stop_after.connected());
  EXPECT_FALSE(silent.exchange(batchOf(1, {cornerScan(1, false)}), 1.0));

  const auto bad = garbage.exchange(batchOf(4, {cornerScan(1, false), cornerScan(2, false)}));
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->batch, 4u);
  ASSERT_EQ(bad->actions.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(bad->actions[i], 200);
    EXPECT_NE(bad->steps[i], 0u);
  }

  test::TestScan scan = cornerScan(9, false);
  for (std::uint32_t b = 1; b <= 2; ++b) {
    const auto moves = stop_after.exchange(batchOf(b, {scan}));
    ASSERT_TRUE(moves) << "batch " << b;
    ASSERT_EQ(moves->actions.size(), 1u);
    EXPECT_TRUE(isAction(moves->actions[0]));
    scan = next(scan);
  }
  EXPECT_FALSE(stop_after.exchange(batchOf(3, {scan}), 1.0));
}

/// Runs agent_node with private parameters `assignments`; returns its exit status and output.
int runAgentNode(const std::string& assignments, int index, std::string* output) {
  // A fresh node name per run, so no parameter of an earlier run is still set.
  const std::string command =
      std::string(AGENT_NODE) + " __name:=bad_agent_" + std::to_string(index) + " " + assignments + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  char buffer[512];
  while (pipe != nullptr && std::fgets(buffer, sizeof buffer, pipe) != nullptr) *output += buffer;
  return pipe == nullptr ? -1 : ::pclose(pipe);
}

TEST(AgentNodeTest, BadParametersStopTheNodeNamingThem) {
  const std::pair<const char*, const char*> cases[] = {
      {"", "~type: required; valid: astar, random,"},
      {"_type:=x", "~type: unknown agent type 'x'; valid: astar, random, wall_follower_left"},
      {"_type:=7", "~type: unknown agent type '7'"},
      {"_type:=explorer _memory:=4x4", "~memory: the window side must be odd"},
      {"_type:=explorer _memory:=big", "~memory: expected KxK with odd K"},
      {"_type:=explorer _memory:=5", "~memory: expected KxK with odd K"},
      {"_type:=explorer _sensor_noise:=1.5", "~sensor_noise: expected a number in [0, 1], got 1.5"},
      {"_type:=explorer _sensor_noise:=high", "~sensor_noise: expected a number"},
      {"_type:=explorer _name:=''", "~name: expected a non-empty agent name"},
  };
  int index = 0;
  for (const auto& c : cases) {
    std::string output;
    const int status = runAgentNode(c.first, index++, &output);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << c.first << " exit status " << status;
    EXPECT_NE(output.find(c.second), std::string::npos) << c.first << " printed:\n" << output;
  }
}

TEST(AgentNodeTest, ANodeletWithABadParameterSaysWhichAndServesNothing) {
  // As a nodelet it cannot exit: it logs why and its manager lives on (here a standalone one, stopped after 5 s).
  std::string output;
  FILE* pipe = ::popen("timeout -s INT 5 /usr/lib/nodelet/nodelet standalone ppp_agents/Agent __name:=bad_nodelet "
                       "_type:=x 2>&1", "r");
  ASSERT_NE(pipe, nullptr);
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  ::pclose(pipe);
  EXPECT_NE(output.find("~type: unknown agent type 'x'; valid: astar, random,"), std::string::npos) << output;
}

TEST(AgentNodeTest, ParametersAcceptAndRefuseWhatEverySourceDoes) {
  // The cases the agents YAML (agent_config_test) and the simulate flags (agent_flags_test) are held to as well.
  int index = 0;
  for (const OptionCase& c : test::agentOptionCases(agentNodeOptionSpecs())) {
    const std::string ns = "/agent_option_case_" + std::to_string(index++);
    if (c.option != "type") ros::param::set(ns + "/type", std::string("explorer"));
    ros::param::set(ns + "/" + c.option, ppp_msgs::yamlParameter(YAML::Load(c.value)));
    std::string error;
    try {
      readAgentNodeParameters(ros::NodeHandle(ns), "explorer");
    } catch (const Error& e) {
      error = e.what();
    }
    if (c.accepted) {
      EXPECT_EQ(error, "") << c.option << " = " << c.value;
    } else {
      EXPECT_EQ(error.rfind("~" + c.option + ": ", 0), 0u) << c.option << " = " << c.value << " gave: " << error;
    }
  }
}

}  // namespace
}  // namespace agents
}  // namespace ppp

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "agent_node_rostest");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
