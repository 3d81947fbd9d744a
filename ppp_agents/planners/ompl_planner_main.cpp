// ompl_planner_node: the OMPL example planner (ompl_planner_node.hpp) in a process of its own.
#include "ompl_planner_node.hpp"
#include "ppp_msgs/node_main.h"

int main(int argc, char** argv) {
  return ppp_msgs::runNode<ppp::planners::OmplPlannerNode>(argc, argv, "ompl_planner");
}
