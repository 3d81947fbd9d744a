#include "dwa_planner_node.hpp"

#include <cmath>
#include <vector>

#include "planner_node_parameters.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace planners {
DwaPlannerNode::DwaPlannerNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh,
                               const std::string& /*node_name*/, bool in_network_thread)
    : parameters_(readDwaNodeParameters(private_nh)),
      window_(parameters_.limits(), parameters_.control_period, parameters_.robot_radius, parameters_.windowOptions()),
      link_(nh, readPlannerFrames(private_nh, nh.getNamespace()), !parameters_.kinematics.empty(),
            in_network_thread, [this](const VelocityRequest& request) { return command(request); }) {
  ROS_INFO("DWA local planner (%s, %.2f m/s, a disc of %.2f m): %s",
           parameters_.kinematics.empty() ? "the grid" : parameters_.kinematics.c_str(),
           parameters_.max_linear_speed, parameters_.robot_radius, link_.topics().c_str());
}

geometry_msgs::Twist DwaPlannerNode::command(const VelocityRequest& request) {
  const nav_msgs::MapMetaData& info = request.map.info;
  if (request.new_episode || !costmap_) {
    costmap_ = std::make_unique<ScanCostmap>(info.width * info.resolution, info.height * info.resolution,
                                             MapPoint{info.origin.position.x, info.origin.position.y},
                                             parameters_.costmap_resolution, parameters_.robot_radius,
                                             parameters_.inflation_radius);
    requests_ = 0;
  }
  // The robot's pose; on the grid its frame is the map's.
  const auto& position = request.pose.pose.pose.position;
  const auto& q = request.pose.pose.pose.orientation;
  const double heading = parameters_.kinematics.empty() ? 0.0 : 2 * std::atan2(q.z, q.w);
  const double cos_h = std::cos(heading), sin_h = std::sin(heading);
  const auto toMap = [&](MapPoint p) {
    return MapPoint{position.x + cos_h * p.x - sin_h * p.y, position.y + sin_h * p.x + cos_h * p.y};
  };
  const sensor_msgs::LaserScan& scan = request.scan;
  std::vector<MapPoint> obstacles, returns;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double range = scan.ranges[i];
    if (!std::isfinite(range) || range < scan.range_min || range > scan.range_max) continue;
    const double angle = scan.angle_min + scan.angle_increment * static_cast<double>(i);
    obstacles.push_back({range * std::cos(angle), range * std::sin(angle)});
    returns.push_back(toMap(obstacles.back()));
  }
  costmap_->mark({position.x, position.y}, returns);
  const MapPoint goal_in_map{request.goal.pose.position.x, request.goal.pose.position.y};
  // The route is planned again every replan_every requests (on the grid at every step), as move_base's global
  // planner runs at its own rate.
  if (parameters_.kinematics.empty() || requests_ % parameters_.replan_every == 0) costmap_->plan(goal_in_map);
  ++requests_;
  const double east = goal_in_map.x - position.x;
  const double north = goal_in_map.y - position.y;
  const MapPoint goal{cos_h * east + sin_h * north, -sin_h * east + cos_h * north};
  if (!std::isfinite(goal.x) || !std::isfinite(goal.y)) {
    throw InvalidArgument("goal", "a goal or pose that is not a finite point");
  }
  const auto& twist = request.pose.twist.twist;
  const BodyVelocity current{twist.linear.x, twist.linear.y, twist.angular.z};
  const BodyVelocity chosen = window_.choose(
      obstacles, goal, current, [&](MapPoint p) { return costmap_->distance(toMap(p)); });
  geometry_msgs::Twist command;
  command.linear.x = chosen.forward;
  command.linear.y = chosen.left;
  command.angular.z = chosen.turn;
  return command;
}

}  // namespace planners
}  // namespace ppp
