#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include "ppp_msgs/MoveBatch.h"
#include "ppp_simulator/agent_lane.hpp"
#include "simulator_parameters.hpp"

namespace ppp {
namespace simulator {

/// The batched conversation with one agent node (or planner bridge): publishes the lane's scans on
/// /NAME/scans, waits for the MoveBatch on /NAME/moves and applies it, with the step timeout, the silent-agent
/// give-up rule and lost-agent detection. Results go to a sink as episodes end; scans to an optional observer
/// (the bag recorder). One runner serves one agent configuration for the node's life and may play several
/// lanes in turn (a hunt plays one per evaluation request).
class LaneRunner {
 public:
  /// Where finished episodes go.
  using ResultSink = std::function<void(const std::vector<EpisodeResult>&)>;
  /// What sees each batch of scans (may be empty).
  using ScanObserver = std::function<void(const std::string& agent, const std::vector<ScanRequest>&)>;

  /// Advertises /NAME/scans and subscribes to /NAME/moves for agent configuration `agent`; `log_rates` logs
  /// each lane's episodes per second when it is done.
  LaneRunner(ros::NodeHandle& nh, const SimulatorParameters& parameters, const agents::AgentConfig& agent,
             ResultSink sink, ScanObserver observer = {}, bool log_rates = true);
  /// Plays every run of `lane` (whose agent is this runner's); returns when it is finished or ROS shuts down.
  void run(AgentLane* lane);

 private:
  bool awaitReply(double seconds);
  bool waitForAgent();
  bool agentAlive() const;
  void onMoves(const ppp_msgs::MoveBatch::ConstPtr& message);
  void report(const std::vector<EpisodeResult>& results);

  SimulatorParameters parameters_;
  agents::AgentConfig agent_;
  ResultSink sink_;
  ScanObserver observer_;
  bool log_rates_;
  AgentLane* lane_ = nullptr;
  bool connected_ = false;
  bool suspect_ = false;        // the agent was lost in an earlier lane: check before playing the next
  ros::CallbackQueue replies_;  // the moves subscription's callbacks, called by the lane's thread
  ros::Publisher scans_;
  ros::Subscriber moves_;       // after replies_: unsubscribes before the queue goes
  std::uint32_t batch_ = 0;     // batches sent so far, over every lane
  std::uint32_t expected_batch_ = 0;
  std::optional<std::vector<MoveReply>> reply_;
  const char* missing_reason_ = reason::kTimeout;  // for episodes the reply has no move for
};

}  // namespace simulator
}  // namespace ppp
