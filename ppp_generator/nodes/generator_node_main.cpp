// generator_node: the generator node (generator_node.hpp) in a process of its own.
#include <ros/ros.h>

#include "generator_node.hpp"
#include "ppp_core/error.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "generator");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  ros::AsyncSpinner spinner(1);  // ~generate, and ~wait_for_set's set while waiting for it
  spinner.start();
  try {
    ppp::generator::GeneratorNode node(nh, private_nh, true);
    return node.run();
  } catch (const ppp::Error& e) {
    ROS_FATAL("generator: %s", e.what());
    return 1;
  }
}
