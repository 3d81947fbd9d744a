#include "reactive_steering.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "ppp_core/error.hpp"
#include "robot_frame.hpp"

namespace ppp {
namespace planners {

BodyVelocity reactiveVelocity(const Heading& heading, bool diff_drive, double max_speed, double max_turn) {
  const double speed = heading.speed * max_speed;
  BodyVelocity velocity;
  if (diff_drive) {
    velocity.forward = speed * std::max(0.0, std::cos(heading.direction));
    velocity.turn = std::clamp(2 * heading.direction, -max_turn, max_turn);
  } else {
    velocity.forward = speed * std::cos(heading.direction);
    velocity.left = speed * std::sin(heading.direction);
  }
  return velocity;
}

ReactiveSteering::ReactiveSteering(const ReactiveNodeParameters& parameters)
    : parameters_(parameters), navigator_(parameters.method) {
  parameters_.validate();
}

Heading ReactiveSteering::steer(const ReactiveView& view, int* invalid_rays) {
  *invalid_rays = 0;
  // The goal in the robot's frame, as the scan's directions are.
  const MapPoint goal = inRobotFrame(MapPoint{view.goal.x / view.range, view.goal.y / view.range}, view.heading);
  if (!std::isfinite(goal.x) || !std::isfinite(goal.y)) {
    throw InvalidArgument("goal", "a goal or pose that is not a finite point");
  }
  // The method's frame: the robot's, or turned so that the goal lies on the centre of the sector just left of
  // straight ahead (the methods choose sector centres), the sectors' seam behind.
  const double turn =
      parameters_.frame == kReactiveFrameGoal ? std::atan2(goal.y, goal.x) - sectorAngle(kReactiveSectors / 2) : 0.0;
  const double radius = parameters_.robot_radius;
  std::vector<double> obstacles;
  if (parameters_.obstacles == kObstaclesFromMemory) {
    if (view.map == nullptr) throw InvalidArgument("map", "no map to cast the obstacle distances on");
    obstacles = sectorObstaclesInMap(*view.map, view.robot, view.heading + turn, view.range, radius);
  } else {
    if (view.scan == nullptr) throw InvalidArgument("scan", "no scan to take the obstacle distances from");
    const LaserRays& scan = *view.scan;
    if (!(std::isfinite(scan.angle_increment) && scan.angle_increment != 0) || !std::isfinite(scan.angle_min)) {
      throw InvalidArgument("scan", "angle_min " + std::to_string(scan.angle_min) + " and angle_increment " +
                                        std::to_string(scan.angle_increment) + " place no ray");
    }
    const LaserRays turned{scan.angle_min - turn, scan.angle_increment, scan.ranges};
    obstacles = parameters_.obstacles == kObstaclesFromScan && radius > 0
                    ? sectorObstaclesForDisc(turned, view.range, radius, invalid_rays)
                    : sectorObstacles(turned, view.range, invalid_rays);
  }
  Heading choice = navigator_.navigate(obstacles, inRobotFrame(goal, turn));
  choice.direction = std::remainder(choice.direction + turn, 2 * M_PI);  // back in the robot's frame
  return choice;
}

BodyVelocity ReactiveSteering::command(const ReactiveView& view, int* invalid_rays) {
  return reactiveVelocity(steer(view, invalid_rays), parameters_.kinematics == kKinematicsDiffDrive,
                          parameters_.max_speed, parameters_.max_turn);
}

}  // namespace planners
}  // namespace ppp
