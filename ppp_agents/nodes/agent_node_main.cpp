// agent_node: the agent node (agent_node.hpp) in a process of its own.
#include <ros/ros.h>

#include "agent_node.hpp"
#include "ppp_core/error.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "agent");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    ppp::agents::AgentNode node(nh, private_nh, ros::this_node::getName(), true);
    ros::spin();
  } catch (const ppp::Error& e) {
    ROS_FATAL("%s", e.what());
    return 1;
  }
  return 0;
}
