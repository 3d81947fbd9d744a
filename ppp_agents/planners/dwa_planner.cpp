#include "dwa_planner.hpp"

#include <cmath>
#include <stdexcept>

#include "ppp_core/error.hpp"
#include "robot_frame.hpp"

namespace ppp {
namespace planners {

DwaPlanner::DwaPlanner(const DwaNodeParameters& parameters)
    : parameters_(parameters),
      window_(parameters_.limits(), parameters_.control_period, parameters_.robot_radius, parameters_.windowOptions()) {}

void DwaPlanner::newEpisode(double width, double height, MapPoint origin) {
  costmap_ = std::make_unique<ScanCostmap>(width, height, origin, parameters_.costmap_resolution,
                                           parameters_.robot_radius, parameters_.inflation_radius);
  requests_ = 0;
}

BodyVelocity DwaPlanner::command(const DwaRequest& request) {
  if (!costmap_) throw std::logic_error("DwaPlanner::command before newEpisode");
  const bool grid = parameters_.kinematics.empty();
  const Pose2D& pose = request.pose;
  const double heading = grid ? 0.0 : pose.theta;
  const double cos_h = std::cos(heading), sin_h = std::sin(heading);
  const auto toMap = [&](MapPoint p) {
    return MapPoint{pose.x + cos_h * p.x - sin_h * p.y, pose.y + sin_h * p.x + cos_h * p.y};
  };
  const LaserReadings& scan = request.scan;
  std::vector<MapPoint> obstacles, returns;
  for (std::size_t i = 0; scan.ranges != nullptr && i < scan.ranges->size(); ++i) {
    const double range = (*scan.ranges)[i];
    if (!std::isfinite(range) || range < scan.range_min || range > scan.range_max) continue;
    const double angle = scan.angle_min + scan.angle_increment * static_cast<double>(i);
    obstacles.push_back({range * std::cos(angle), range * std::sin(angle)});
    returns.push_back(toMap(obstacles.back()));
  }
  costmap_->mark({pose.x, pose.y}, returns);
  if (grid || requests_ % parameters_.replan_every == 0) costmap_->plan(request.goal);
  ++requests_;
  const double east = request.goal.x - pose.x;
  const double north = request.goal.y - pose.y;
  const MapPoint goal = inRobotFrame(MapPoint{east, north}, heading);
  if (!std::isfinite(goal.x) || !std::isfinite(goal.y)) {
    throw InvalidArgument("goal", "a goal or pose that is not a finite point");
  }
  return window_.choose(obstacles, goal, request.velocity,
                        [&](MapPoint p) { return costmap_->distance(toMap(p)); });
}

}  // namespace planners
}  // namespace ppp
