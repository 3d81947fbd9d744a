// agent_node: the agent node (agent_node.hpp) in a process of its own.
#include "agent_node.hpp"
#include "ppp_msgs/node_main.h"

int main(int argc, char** argv) { return ppp_msgs::runNode<ppp::agents::AgentNode>(argc, argv, "agent"); }
