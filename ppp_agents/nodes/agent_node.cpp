// agent_node: one agent configuration serving many episodes at once for the simulator node.
//   subscribes  scans (ppp_msgs/ScanBatch)  one scan per active episode of this agent
//   publishes   moves (ppp_msgs/MoveBatch)  one move per scan, sent as soon as the batch is answered
//   parameters  ~type (required: a built-in type; planner agents play through planner_bridge_node), ~name
//               (default: the node's name) and every other option an agent plays by (~memory, ~sensor_noise,
//               ~goal_seeking, ...: docs/reference/options.md#agents); the simulator applies the sensor noise
// Topics are relative: start the node as <node name="NAME" ...> (or with ns/remapping) to get /NAME/scans.
#include <ros/ros.h>

#include "agent_node_parameters.hpp"
#include "ppp_agents/protocol/batch_responder.hpp"
#include "ppp_core/error.hpp"
#include "ppp_msgs/inline_callback_queue.h"
#include "ppp_msgs/graph_names.h"

namespace ppp {
namespace agents {

/// Answers every ScanBatch at once with one MoveBatch, through the agents library.
class AgentNode {
 public:
  /// Subscribes and advertises in the node's namespace. @throws InvalidArgument for a bad configuration.
  AgentNode(ros::NodeHandle& nh, const AgentConfig& config)
      : responder_(config),
        moves_(nh.advertise<ppp_msgs::MoveBatch>(ppp_msgs::topics::kMoves, 10)),
        scans_(subscribeInline(nh)) {}

  /// The resolved topic names, for the log.
  std::string topics() const { return scans_.getTopic() + " -> " + moves_.getTopic(); }

 private:
  // Scans are answered in roscpp's network thread as they are read (InlineCallbackQueue): the batch's moves go
  // out without waking a spinner thread to answer and the network thread again to send.
  ros::Subscriber subscribeInline(ros::NodeHandle& nh) {
    return ppp_msgs::subscribeInline<ppp_msgs::ScanBatch>(
        nh, ppp_msgs::topics::kScans, 10, [this](const ppp_msgs::ScanBatch::ConstPtr& batch) { onScans(batch); },
        &inline_queue_);
  }

  void onScans(const ppp_msgs::ScanBatch::ConstPtr& batch) {
    ppp_msgs::MoveBatch moves = responder_.answer(*batch);
    moves.header.stamp = ros::Time::now();
    moves_.publish(moves);
  }

  protocol::BatchResponder responder_;
  ppp_msgs::InlineCallbackQueue inline_queue_;
  ros::Publisher moves_;
  ros::Subscriber scans_;
};

}  // namespace agents
}  // namespace ppp

int main(int argc, char** argv) {
  ros::init(argc, argv, "agent");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    const ppp::agents::AgentConfig config =
        ppp::agents::readAgentNodeParameters(private_nh, ppp::agents::baseName(ros::this_node::getName()));
    ppp::agents::AgentNode node(nh, config);
    ROS_INFO("agent '%s': type %s, memory %s, sensor noise %g (applied by the simulator); %s", config.name.c_str(),
             config.type.c_str(), ppp::agents::memoryWindowText(config.memory_window).c_str(), config.sensor_noise,
             node.topics().c_str());
    const std::string expected =
        ppp_msgs::topics::under(ppp::agents::agentGraphName(config.name), ppp_msgs::topics::kScans);
    if (node.topics().rfind(expected + " ", 0) != 0) {
      ROS_WARN("agent '%s' listens on %s, but the simulator sends its scans to %s: remap scans/moves or rename "
               "the node", config.name.c_str(), node.topics().c_str(), expected.c_str());
    }
    ros::spin();
  } catch (const ppp::Error& e) {
    ROS_FATAL("%s", e.what());
    return 1;
  }
  return 0;
}
