// zoo_planner_node: the zoo planner (zoo_planner_node.hpp) in a process of its own.
#include "ppp_msgs/node_main.h"
#include "zoo_planner_node.hpp"

int main(int argc, char** argv) { return ppp_msgs::runNode<ppp::planners::ZooPlannerNode>(argc, argv, "zoo_planner"); }
