// The agent nodes as nodelets (nodelet_plugins.xml), answering in the simulator's thread when the simulator is a
// nodelet of the same manager:
//   ppp_agents/Agent          the agent node (agent_node.hpp)
//   ppp_agents/PlannerBridge  the planner bridge (bridge_node.hpp), asking a planner nodelet of the manager in
//                             that thread too
#include <pluginlib/class_list_macros.hpp>

#include "agent_node.hpp"
#include "bridge_node.hpp"
#include "ppp_msgs/nodelet_of.h"

namespace ppp {
namespace agents {

class AgentNodelet : public ppp_msgs::NodeletOf<AgentNode> {};
class PlannerBridgeNodelet : public ppp_msgs::NodeletOf<BridgeNode> {};

}  // namespace agents
}  // namespace ppp

PLUGINLIB_EXPORT_CLASS(ppp::agents::AgentNodelet, nodelet::Nodelet)
PLUGINLIB_EXPORT_CLASS(ppp::agents::PlannerBridgeNodelet, nodelet::Nodelet)
