#include "bridge_node.hpp"

#include "ppp_core/error.hpp"

namespace ppp {
namespace agents {

BridgeNode::BridgeNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& /*node_name*/,
                       bool in_network_thread)
    : nh_(nh),
      parameters_(readBridgeParameters(private_nh, nh.getNamespace())),
      bridge_(nh_, parameters_, in_network_thread),
      continuous_(bridge_.link(), parameters_, in_network_thread) {
  ROS_INFO("bridge '%s': waiting for a planner on %s", parameters_.config.name.c_str(),
           bridge_.plannerTopics().c_str());
  if (in_network_thread) {
    connect();
    return;
  }
  connecting_ = std::thread([this] {
    try {
      connect();
    } catch (const Error& e) {
      ROS_FATAL("bridge '%s': %s", parameters_.config.name.c_str(), e.what());
    }
  });
}

BridgeNode::~BridgeNode() {
  bridge_.stop();
  if (connecting_.joinable()) connecting_.join();
}

void BridgeNode::connect() {
  if (!bridge_.waitForPlanner()) return;
  ROS_INFO("bridge '%s': planner connected", parameters_.config.name.c_str());
  // The simulator talks to the grid's bridge or the continuous one, as the agent's motion says: both listen.
  bridge_.serve(nh_);
  continuous_.serve(nh_);
}

}  // namespace agents
}  // namespace ppp
