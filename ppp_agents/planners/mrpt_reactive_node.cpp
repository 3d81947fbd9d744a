#include "mrpt_reactive_node.hpp"

#include <cmath>
#include <optional>
#include <string>

#include "planner_node.hpp"
#include "planner_node_parameters.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace planners {

ReactiveNode::ReactiveNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& /*node_name*/,
                           bool in_network_thread)
    : parameters_(readReactiveNodeParameters(private_nh)),
      steering_(parameters_),
      link_(nh, readPlannerFrames(private_nh, nh.getNamespace()),
            continuous() ? readPlannerPeriod(private_nh).control_period : 0.0, in_network_thread,
            [this](const VelocityRequest& request) { return command(request); }) {
  ROS_INFO("MRPT reactive navigator (%s, obstacles from the %s for a body of %g m in the %s frame, range %s): %s",
           parameters_.method.c_str(), parameters_.obstacles.c_str(), parameters_.robot_radius,
           parameters_.frame.c_str(),
           parameters_.range > 0 ? (std::to_string(parameters_.range) + " m").c_str() : "the scan's range_max",
           link_.topics().c_str());
}

geometry_msgs::Twist ReactiveNode::command(const VelocityRequest& request) {
  if (request.new_episode) steering_.reset();  // a new method object: ND remembers its last choice
  const sensor_msgs::LaserScan& scan = request.scan;
  ReactiveView view;
  view.range = parameters_.range > 0 ? parameters_.range : scan.range_max;
  if (!(view.range > 0) || !std::isfinite(view.range)) {
    throw InvalidArgument("range", "the scan's range_max is " + std::to_string(scan.range_max) +
                                       ": set ~range to the metres obstacle distances are fractions of");
  }
  view.robot = MapPoint{request.pose.pose.pose.position.x, request.pose.pose.pose.position.y};
  const auto& q = request.pose.pose.pose.orientation;
  view.heading = continuous() ? 2 * std::atan2(q.z, q.w) : 0.0;  // on the grid the robot's frame is the map's
  view.goal = MapPoint{request.goal.pose.position.x - view.robot.x, request.goal.pose.position.y - view.robot.y};
  const LaserRays rays{scan.angle_min, scan.angle_increment, scan.ranges};
  view.scan = &rays;
  std::optional<GridMap> map;
  if (parameters_.obstacles == kObstaclesFromMemory) {
    map.emplace(gridMapOf(request.map, true, 0));
    view.map = &*map;
  }
  int invalid = 0;
  const BodyVelocity velocity = steering_.command(view, &invalid);
  if (invalid > 0) {
    ROS_WARN_THROTTLE(5, "scan at %.3f: %d of %zu rays are NaN (no reading), taken as obstacles at the robot",
                      scan.header.stamp.toSec(), invalid, scan.ranges.size());
  }
  geometry_msgs::Twist twist;  // on the grid: east and north; in continuous motion: the robot's frame
  twist.linear.x = velocity.forward;
  twist.linear.y = velocity.left;
  twist.angular.z = velocity.turn;
  return twist;
}

}  // namespace planners
}  // namespace ppp
