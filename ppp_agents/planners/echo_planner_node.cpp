#include "echo_planner_node.hpp"

#include "planner_node_parameters.hpp"

namespace ppp {
namespace planners {

EchoPlannerNode::EchoPlannerNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh,
                                 const std::string& /*node_name*/, bool in_network_thread)
    : link_(nh, readPlannerFrames(private_nh, nh.getNamespace()), readPlannerPeriod(private_nh).control_period,
            in_network_thread,
            [](const VelocityRequest&) { return geometry_msgs::Twist(); }) {
  ROS_INFO("echo planner: %s", link_.topics().c_str());
}

}  // namespace planners
}  // namespace ppp
