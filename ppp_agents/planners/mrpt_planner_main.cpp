// mrpt_planner_node: the MRPT example planner (mrpt_planner_node.hpp) in a process of its own.
#include "mrpt_planner_node.hpp"
#include "ppp_msgs/node_main.h"

int main(int argc, char** argv) {
  return ppp_msgs::runNode<ppp::planners::MrptPlannerNode>(argc, argv, "mrpt_planner");
}
