// The nodelet ppp_agents/Agent: the agent node (agent_node.hpp) in a nodelet manager, answering in the simulator's
// thread when the simulator is a nodelet of the same manager.
#include <pluginlib/class_list_macros.hpp>

#include "agent_node.hpp"
#include "ppp_msgs/nodelet_of.h"

namespace ppp {
namespace agents {

class AgentNodelet : public ppp_msgs::NodeletOf<AgentNode> {};

}  // namespace agents
}  // namespace ppp

PLUGINLIB_EXPORT_CLASS(ppp::agents::AgentNodelet, nodelet::Nodelet)
