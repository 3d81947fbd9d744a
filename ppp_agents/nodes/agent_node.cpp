#include "agent_node.hpp"

#include <boost/make_shared.hpp>

#include "agent_node_parameters.hpp"
#include "ppp_agents/continuous/continuous_agent.hpp"
#include "ppp_msgs/graph_names.h"

namespace ppp {
namespace agents {

AgentNode::AgentNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& node_name,
                     bool in_network_thread)
    : config_(readAgentNodeParameters(private_nh, baseName(node_name))),
      responder_(config_),
      queue_(in_network_thread),
      moves_(nh.advertise<ppp_msgs::MoveBatch>(ppp_msgs::topics::kMoves, 10)),
      scans_(ppp_msgs::subscribeLockstep<ppp_msgs::ScanBatch>(
          nh, ppp_msgs::topics::kScans, 10, [this](const ppp_msgs::ScanBatch::ConstPtr& batch) { onScans(batch); },
          queue_.get())) {
  if (movesContinuously(config_)) {
    continuous_ = std::make_unique<protocol::ContinuousResponder>(config_);
    commands_ = nh.advertise<ppp_msgs::CommandBatch>(ppp_msgs::topics::kCommands, 10);
    sensing_ = ppp_msgs::subscribeLockstep<ppp_msgs::SensingBatch>(
        nh, ppp_msgs::topics::kSensing, 10,
        [this](const ppp_msgs::SensingBatch::ConstPtr& batch) { onSensing(batch); }, queue_.get());
  }
  const std::string topics = scans_.getTopic() + " -> " + moves_.getTopic();
  ROS_INFO("agent '%s': type %s, memory %s, sensor noise %g (applied by the simulator); %s", config_.name.c_str(),
           config_.type.c_str(), memoryWindowText(config_.memory_window).c_str(), config_.sensor_noise,
           topics.c_str());
  // /NAME/scans, or /NAME/instance_K/scans for one of several instances.
  const std::string expected = ppp_msgs::topics::under(agentGraphName(config_.name), ppp_msgs::topics::kScans);
  const std::string instances = ppp_msgs::topics::under(agentGraphName(config_.name), "instance_");
  if (scans_.getTopic() != expected && scans_.getTopic().rfind(instances, 0) != 0) {
    ROS_WARN("agent '%s' listens on %s, but the simulator sends its scans to %s: remap scans/moves or rename the node",
             config_.name.c_str(), topics.c_str(), expected.c_str());
  }
}

void AgentNode::onScans(const ppp_msgs::ScanBatch::ConstPtr& batch) {
  // A new message per batch, published by pointer: a subscriber in the same process gets this very object.
  auto moves = boost::make_shared<ppp_msgs::MoveBatch>(responder_.answer(*batch));
  moves->header.stamp = ros::Time::now();
  moves_.publish(moves);
}

void AgentNode::onSensing(const ppp_msgs::SensingBatch::ConstPtr& batch) {
  auto commands = boost::make_shared<ppp_msgs::CommandBatch>(continuous_->answer(*batch));
  commands->header.stamp = ros::Time::now();
  commands_.publish(commands);
}

}  // namespace agents
}  // namespace ppp
