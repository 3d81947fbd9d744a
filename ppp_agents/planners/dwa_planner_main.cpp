// dwa_planner_node: the DWA example (dwa_planner_node.hpp) in a process of its own.
#include "dwa_planner_node.hpp"
#include "ppp_msgs/node_main.h"

int main(int argc, char** argv) { return ppp_msgs::runNode<ppp::planners::DwaPlannerNode>(argc, argv, "dwa_planner"); }
