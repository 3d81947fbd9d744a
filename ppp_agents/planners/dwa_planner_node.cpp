#include "dwa_planner_node.hpp"

#include <cmath>

#include "planner_node_parameters.hpp"

namespace ppp {
namespace planners {
DwaPlannerNode::DwaPlannerNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh,
                               const std::string& /*node_name*/, bool in_network_thread)
    : parameters_(readDwaNodeParameters(private_nh)),
      planner_(parameters_),
      link_(nh, readPlannerFrames(private_nh, nh.getNamespace()),
            parameters_.kinematics.empty() ? 0.0 : parameters_.control_period,
            in_network_thread, [this](const VelocityRequest& request) { return command(request); }) {
  ROS_INFO("DWA local planner (%s, %.2f m/s, a disc of %.2f m): %s",
           parameters_.kinematics.empty() ? "the grid" : parameters_.kinematics.c_str(),
           parameters_.max_linear_speed, parameters_.robot_radius, link_.topics().c_str());
}

geometry_msgs::Twist DwaPlannerNode::command(const VelocityRequest& request) {
  const nav_msgs::MapMetaData& info = request.map.info;
  if (request.new_episode || !planner_.started()) {
    planner_.newEpisode(info.width * info.resolution, info.height * info.resolution,
                        MapPoint{info.origin.position.x, info.origin.position.y});
  }
  const auto& position = request.pose.pose.pose.position;
  const auto& q = request.pose.pose.pose.orientation;
  const auto& twist = request.pose.twist.twist;
  const sensor_msgs::LaserScan& scan = request.scan;
  DwaRequest asked;
  asked.pose = Pose2D{position.x, position.y, 2 * std::atan2(q.z, q.w)};
  asked.velocity = BodyVelocity{twist.linear.x, twist.linear.y, twist.angular.z};
  asked.goal = MapPoint{request.goal.pose.position.x, request.goal.pose.position.y};
  asked.scan = LaserReadings{&scan.ranges, scan.angle_min, scan.angle_increment, scan.range_min, scan.range_max};
  const BodyVelocity chosen = planner_.command(asked);
  geometry_msgs::Twist command;
  command.linear.x = chosen.forward;
  command.linear.y = chosen.left;
  command.angular.z = chosen.turn;
  return command;
}

}  // namespace planners
}  // namespace ppp
