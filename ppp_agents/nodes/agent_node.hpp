#pragma once

// The agent node: one agent configuration serving many episodes at once for the simulator node.
//   subscribes  scans (ppp_msgs/ScanBatch)  one scan per active episode of this agent
//   publishes   moves (ppp_msgs/MoveBatch)  one move per scan, sent as soon as the batch is answered
//   subscribes  sensing (ppp_msgs/SensingBatch)  continuous motion, for an agent that moves so (astar): one
//               control period of each active episode
//   publishes   commands (ppp_msgs/CommandBatch)  one velocity command per episode of the sensing batch
//   parameters  ~type (required: a built-in type; planner agents play through planner_bridge_node), ~name
//               (default: the node's name) and every other option an agent plays by (~memory, ~sensor_noise,
//               ~goal_seeking, ...: docs/reference/options.md#agents); the simulator applies the sensor noise
// Topics are relative: start the node as <node name="NAME" ...> (or with ns/remapping) to get /NAME/scans.
// It runs as a process of its own (agent_node) or as the nodelet ppp_agents/Agent.

#include <memory>
#include <string>

#include <ros/ros.h>

#include "ppp_agents/agent_config.hpp"
#include "ppp_agents/protocol/batch_responder.hpp"
#include "ppp_agents/protocol/continuous_responder.hpp"
#include "ppp_msgs/MoveBatch.h"
#include "ppp_msgs/ScanBatch.h"
#include "ppp_msgs/lockstep_queue.h"

namespace ppp {
namespace agents {

/// Answers every ScanBatch at once with one MoveBatch, and every SensingBatch with one CommandBatch when the agent
/// moves in continuous motion too, through the agents library.
class AgentNode {
 public:
  /// Reads the private parameters, subscribes and advertises in `nh`'s namespace and logs what it serves; with
  /// `in_network_thread` batches are answered in roscpp's network thread as they are read (a node in a process of
  /// its own); else (a nodelet) in the thread of a simulator in the same manager that published the batch, or else
  /// in a thread of the node's own (ppp_msgs/hand_over.h). `node_name` is the node's graph name.
  /// @throws InvalidArgument naming the parameter for a bad configuration.
  AgentNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& node_name,
            bool in_network_thread);

 private:
  void onScans(const ppp_msgs::ScanBatch::ConstPtr& batch);
  void onSensing(const ppp_msgs::SensingBatch::ConstPtr& batch);

  AgentConfig config_;
  protocol::BatchResponder responder_;
  std::unique_ptr<protocol::ContinuousResponder> continuous_;  // null for an agent that moves only on the grid
  ppp_msgs::LockstepQueue queue_;
  ros::Publisher moves_;
  ros::Subscriber scans_;
  ros::Publisher commands_;
  ros::Subscriber sensing_;
};

}  // namespace agents
}  // namespace ppp
