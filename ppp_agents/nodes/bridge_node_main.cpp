// planner_bridge_node: the planner bridge (bridge_node.hpp) in a process of its own.
#include "bridge_node.hpp"
#include "ppp_msgs/node_main.h"

int main(int argc, char** argv) { return ppp_msgs::runNode<ppp::agents::BridgeNode>(argc, argv, "bridge"); }
