#pragma once

#include <memory>
#include <vector>

#include "dynamic_window.hpp"
#include "planner_node_options.hpp"
#include "scan_costmap.hpp"
#include "ppp_core/kinematics.hpp"
#include "ppp_core/map_frame.hpp"

namespace ppp {
namespace planners {

/// A laser scan as sensor_msgs/LaserScan gives it: reading i at angle_min + i x angle_increment from the robot's
/// heading; readings that are not finite or lie outside [range_min, range_max] are no return.
struct LaserReadings {
  const std::vector<float>* ranges = nullptr;
  double angle_min = 0;
  double angle_increment = 0;
  double range_min = 0;
  double range_max = 0;
};

/// What the DWA example is asked in one request.
struct DwaRequest {
  Pose2D pose;            ///< The robot in the map frame (on the grid the heading is ignored: the map's frame).
  BodyVelocity velocity;  ///< Its velocity, robot frame.
  MapPoint goal;          ///< The goal, map frame.
  LaserReadings scan;     ///< This request's scan.
};

/// The DWA example's planning, ROS-free (the node only converts messages): each request marks the scan's returns
/// in this episode's ScanCostmap (over the map's extent), plans the route to the goal again every replan_every
/// requests (on the grid at every one, as move_base's global planner runs at its own rate), and lets the
/// DynamicWindow choose among the velocities it can reach, scoring each rollout's end by that route.
class DwaPlanner {
 public:
  /// @throws InvalidArgument naming a bad parameter.
  explicit DwaPlanner(const DwaNodeParameters& parameters);
  /// A new episode on a map of `width` x `height` metres whose bottom-left corner is `origin`: its memory starts
  /// empty.
  void newEpisode(double width, double height, MapPoint origin);
  /// True once an episode has begun.
  bool started() const { return costmap_ != nullptr; }
  /// The velocity command for `request` (robot frame; on the grid east and north). @throws InvalidArgument naming
  /// "goal" for a goal or pose that is not finite; std::logic_error before newEpisode().
  BodyVelocity command(const DwaRequest& request);

 private:
  DwaNodeParameters parameters_;
  DynamicWindow window_;
  std::unique_ptr<ScanCostmap> costmap_;  // this episode's
  long requests_ = 0;                     // this episode's so far
};

}  // namespace planners
}  // namespace ppp
