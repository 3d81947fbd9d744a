#pragma once

#include <exception>

#include <ros/ros.h>

namespace ppp_msgs {

/// The main() of a node class that serves from its callbacks alone (the class nodelet_of.h wraps as a nodelet): a
/// process named `default_name` unless remapped, running `Node(public handle, private handle, graph name,
/// in_network_thread = true)` until ROS shuts down. A node that cannot start logs why and exits with status 1.
template <typename Node>
int runNode(int argc, char** argv, const char* default_name) {
  ros::init(argc, argv, default_name);
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    Node node(nh, private_nh, ros::this_node::getName(), true);
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL("%s", e.what());
    return 1;
  }
  return 0;
}

}  // namespace ppp_msgs
