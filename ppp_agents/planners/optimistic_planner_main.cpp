// optimistic_planner_node: the optimistic example planner (optimistic_planner_node.hpp) in a process of its own.
#include "optimistic_planner_node.hpp"
#include "ppp_msgs/node_main.h"

int main(int argc, char** argv) {
  return ppp_msgs::runNode<ppp::planners::OptimisticPlannerNode>(argc, argv, "optimistic_planner");
}
