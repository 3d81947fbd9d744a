#pragma once

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include "ppp_msgs/CommandBatch.h"
#include "ppp_msgs/MoveBatch.h"
#include "ppp_msgs/ScanBatch.h"
#include "ppp_msgs/SensingBatch.h"
#include "ppp_msgs/graph_names.h"
#include "ppp_msgs/inline_callback_queue.h"
#include "ppp_agents/agent_lane.hpp"
#include "ppp_agents/continuous/continuous_lane.hpp"
#include "simulator_parameters.hpp"

namespace ppp {
namespace simulator {

/// What the simulator's parts need to know of the node they run in.
struct NodeControl {
  /// True once the node is to stop: ROS shut down, its nodelet is being unloaded, or a lane failed for good.
  std::function<bool()> stopping;
  /// Agents' replies are handled in roscpp's network thread as they are read (a node in a process of its own),
  /// or else by each lane's own thread, the one in LaneRunner::run() (a nodelet: see ppp_msgs::subscribeLockstep).
  bool in_network_thread = true;
};

/// The grid model's lockstep: an AgentLane's scans out on /NAME/scans, its moves back on /NAME/moves.
struct GridLockstep {
  using Lane = agents::AgentLane;
  using Requests = ppp_msgs::ScanBatch;
  using Replies = ppp_msgs::MoveBatch;
  using Request = protocol::ScanRequest;
  static constexpr const char* kRequestTopic = ppp_msgs::topics::kScans;
  static constexpr const char* kReplyTopic = ppp_msgs::topics::kMoves;
};

/// Continuous motion's lockstep: a ContinuousLane's sensing out on /NAME/sensing, velocity commands back on
/// /NAME/commands.
struct ContinuousLockstep {
  using Lane = agents::ContinuousLane;
  using Requests = ppp_msgs::SensingBatch;
  using Replies = ppp_msgs::CommandBatch;
  using Request = agents::ContinuousRequest;
  static constexpr const char* kRequestTopic = ppp_msgs::topics::kSensing;
  static constexpr const char* kReplyTopic = ppp_msgs::topics::kCommands;
};

/// The batched conversation with one agent node (or planner bridge) in one motion model (`Lockstep`, one of the
/// two above): publishes the lane's requests (scans, or sensing) on /NAME/scans (/NAME/sensing), waits for the
/// replies (moves, or commands) on /NAME/moves (/NAME/commands) and applies them, with the step timeout, the silent-agent
/// give-up rule and lost-agent detection. Results go to a sink as episodes end; scans to an optional observer
/// (the bag recorder). One runner serves one agent configuration for the node's life and may play several
/// lanes in turn (a hunt plays one per evaluation request). In a node of its own each reply is applied, and the
/// next batch sent, in roscpp's network thread as the reply is read (no thread hand-over per batch), and the thread
/// in run() only watches for the step timeout, a lost agent and shutdown; in a nodelet that thread takes the
/// replies itself from a queue of the runner's own. An agent nodelet in the same manager answers each batch in that
/// thread too, as it is published (ppp_msgs/hand_over.h): a round trip then wakes no thread at all.
template <class Lockstep>
class LaneRunnerOf {
 public:
  using Lane = typename Lockstep::Lane;
  /// Where finished episodes go.
  using ResultSink = std::function<void(const std::vector<agents::EpisodeResult>&)>;
  /// What sees each request sent (may be empty).
  using ScanObserver = std::function<void(const std::string& agent, const typename Lockstep::Request&)>;

  /// Advertises the requests' topic under /NS and subscribes to the replies' for instance `share.index` of the
  /// `share.count` instances of agent configuration `agent` (NS = agents::instanceGraphName); `log_rates` logs
  /// each lane's episodes per second when it is done.
  LaneRunnerOf(ros::NodeHandle& nh, const SimulatorParameters& parameters, const NodeControl& control,
               const agents::AgentConfig& agent, agents::LaneShare share, ResultSink sink, ScanObserver observer = {},
               bool log_rates = true);
  /// Plays every run of `lane` (whose agent is this runner's); returns when it is finished or the node stops.
  /// @throws what the result sink threw (an unwritable results file, say).
  void run(Lane* lane);

 private:
  void sendBatch();
  void answerSilence();
  bool waitForAgent();
  bool agentAlive() const;
  void onReplies(const typename Lockstep::Replies::ConstPtr& message);
  void report(const std::vector<agents::EpisodeResult>& results);

  SimulatorParameters parameters_;
  NodeControl control_;
  agents::AgentConfig agent_;
  std::string label_;  // "agent 'NAME'", with the instance when there are several
  ResultSink sink_;
  ScanObserver observer_;
  bool log_rates_;
  double step_timeout_;
  bool connected_ = false;
  bool suspect_ = false;  // the agent was lost in an earlier lane: check before playing the next
  std::mutex mutex_;      // guards everything below, shared by run() and the network thread
  std::condition_variable lane_done_;  // the lane finished or the sink failed
  Lane* lane_ = nullptr;               // the lane being played; null between lanes
  std::exception_ptr failure_;         // what the sink threw in the network thread
  std::uint32_t batch_ = 0;            // batches sent so far, over every lane
  std::uint32_t expected_batch_ = 0;   // the batch awaiting its reply; 0 when none
  ros::WallTime deadline_;             // when the awaited batch counts as unanswered
  std::vector<typename Lockstep::Request> requests_;  // a continuous lane's requests, reused batch to batch
  std::unique_ptr<ppp_msgs::InlineCallbackQueue> inline_replies_;  // runs onReplies in the network thread, or
  std::unique_ptr<ros::CallbackQueue> queued_replies_;             // holds the replies for run() (a nodelet)
  ros::Publisher request_publisher_;
  ros::Subscriber reply_subscriber_;  // after replies_: unsubscribes before the queue goes
};

/// The grid model's runner (experiments, hunts, shrinks).
using LaneRunner = LaneRunnerOf<GridLockstep>;
/// Continuous motion's runner (experiments).
using ContinuousLaneRunner = LaneRunnerOf<ContinuousLockstep>;

}  // namespace simulator
}  // namespace ppp
