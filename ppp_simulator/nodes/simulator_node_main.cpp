// simulator_node: the simulator node (simulator_node.hpp) in a process of its own; exits when its experiment is
// finished, with run()'s status.
#include <ros/ros.h>

#include "ppp_core/error.hpp"
#include "simulator_node.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "simulator");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  int status = 1;
  try {
    ppp::simulator::SimulatorNode node(nh, private_nh, true);
    status = node.run();
  } catch (const ppp::Error& e) {
    ROS_FATAL("simulator: %s", e.what());
  }
  spinner.stop();
  ros::shutdown();
  return status;
}
