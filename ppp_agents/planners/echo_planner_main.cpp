// echo_planner_node: the echo planner (echo_planner_node.hpp) in a process of its own.
#include "echo_planner_node.hpp"
#include "ppp_msgs/node_main.h"

int main(int argc, char** argv) {
  return ppp_msgs::runNode<ppp::planners::EchoPlannerNode>(argc, argv, "echo_planner");
}
