// mrpt_reactive_node: the MRPT reactive example (mrpt_reactive_node.hpp) in a process of its own.
#include "mrpt_reactive_node.hpp"
#include "ppp_msgs/node_main.h"

int main(int argc, char** argv) {
  return ppp_msgs::runNode<ppp::planners::ReactiveNode>(argc, argv, "mrpt_reactive");
}
