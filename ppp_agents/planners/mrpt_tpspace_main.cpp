// mrpt_tpspace_node: the TP-space example (mrpt_tpspace_node.hpp) in a process of its own.
#include "mrpt_tpspace_node.hpp"
#include "ppp_msgs/node_main.h"

int main(int argc, char** argv) {
  return ppp_msgs::runNode<ppp::planners::TpSpaceNode>(argc, argv, "mrpt_tpspace");
}
