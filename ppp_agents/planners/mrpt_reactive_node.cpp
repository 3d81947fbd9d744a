#include "mrpt_reactive_node.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "planner_node.hpp"
#include "planner_node_parameters.hpp"
#include "robot_frame.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/motion_options.hpp"

namespace ppp {
namespace planners {

ReactiveNode::ReactiveNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& /*node_name*/,
                           bool in_network_thread)
    : parameters_(readReactiveNodeParameters(private_nh)),
      navigator_(parameters_.method),
      link_(nh, readPlannerFrames(private_nh, nh.getNamespace()), continuous(), in_network_thread,
            [this](const VelocityRequest& request) { return command(request); }) {
  ROS_INFO("MRPT reactive navigator (%s, obstacles from the %s for a body of %g m, range %s): %s",
           parameters_.method.c_str(), parameters_.obstacles.c_str(), parameters_.robot_radius,
           parameters_.range > 0 ? (std::to_string(parameters_.range) + " m").c_str() : "the scan's range_max",
           link_.topics().c_str());
}

geometry_msgs::Twist ReactiveNode::command(const VelocityRequest& request) {
  if (request.new_episode) navigator_.reset();  // a new method object: ND remembers its last choice
  const BodyVelocity velocity = reactiveVelocity(steer(request), parameters_.kinematics == kKinematicsDiffDrive,
                                                 parameters_.max_speed, parameters_.max_turn);
  geometry_msgs::Twist twist;  // on the grid: east and north; in continuous motion: the robot's frame
  twist.linear.x = velocity.forward;
  twist.linear.y = velocity.left;
  twist.angular.z = velocity.turn;
  return twist;
}

Heading ReactiveNode::steer(const VelocityRequest& request) {
  const sensor_msgs::LaserScan& scan = request.scan;
  const double range = parameters_.range > 0 ? parameters_.range : scan.range_max;
  if (!(range > 0) || !std::isfinite(range)) {
    throw InvalidArgument("range", "the scan's range_max is " + std::to_string(scan.range_max) +
                                       ": set ~range to the metres obstacle distances are fractions of");
  }
  const MapPoint robot{request.pose.pose.pose.position.x, request.pose.pose.pose.position.y};
  const auto& q = request.pose.pose.pose.orientation;
  const double heading = continuous() ? 2 * std::atan2(q.z, q.w) : 0.0;  // on the grid the robot's frame is the map's
  std::vector<double> obstacles;
  const double radius = parameters_.robot_radius;
  if (parameters_.obstacles == kObstaclesFromMemory) {
    obstacles = sectorObstaclesInMap(gridMapOf(request.map, true, 0), robot, heading, range, radius);
  } else {
    if (!(std::isfinite(scan.angle_increment) && scan.angle_increment != 0) || !std::isfinite(scan.angle_min)) {
      throw InvalidArgument("scan", "angle_min " + std::to_string(scan.angle_min) + " and angle_increment " +
                                        std::to_string(scan.angle_increment) + " place no ray");
    }
    int invalid = 0;
    const LaserRays rays{scan.angle_min, scan.angle_increment, scan.ranges};
    obstacles = parameters_.obstacles == kObstaclesFromScan && radius > 0
                    ? sectorObstaclesForDisc(rays, range, radius, &invalid)
                    : sectorObstacles(rays, range, &invalid);
    if (invalid > 0) {
      ROS_WARN_THROTTLE(5, "scan at %.3f: %d of %zu rays are NaN (no reading), taken as obstacles at the robot",
                        scan.header.stamp.toSec(), invalid, scan.ranges.size());
    }
  }
  // The goal in the robot's frame, as the scan's directions are.
  const double east = (request.goal.pose.position.x - robot.x) / range;
  const double north = (request.goal.pose.position.y - robot.y) / range;
  const MapPoint target = inRobotFrame(MapPoint{east, north}, heading);
  if (!std::isfinite(target.x) || !std::isfinite(target.y)) {
    throw InvalidArgument("goal", "a goal or pose that is not a finite point");
  }
  return navigator_.navigate(obstacles, target);
}

}  // namespace planners
}  // namespace ppp
