#pragma once

#include <vector>

#include "grid_map.hpp"
#include "mrpt_reactive_navigator.hpp"
#include "planner_node_options.hpp"
#include "ppp_core/kinematics.hpp"
#include "ppp_core/map_frame.hpp"
#include "sector_obstacles.hpp"

namespace ppp {
namespace planners {

/// The velocity mrpt_reactive_node commands for a method's `heading` (its direction relative to the robot's x axis)
/// with `max_speed` metres per second at the method's full speed: a diff-drive robot turns towards the direction
/// at twice its angle (at most `max_turn` rad/s) and drives as much of the speed as lies ahead; any other robot
/// (holonomic, or on the grid) drives along the direction.
BodyVelocity reactiveVelocity(const Heading& heading, bool diff_drive, double max_speed, double max_turn);

/// What the robot knows at one step.
struct ReactiveView {
  MapPoint goal;                    ///< Map-frame metres from the robot to the goal (east, north).
  double heading = 0;               ///< Radians of the robot's x axis in the map frame (on the grid 0).
  double range = 0;                 ///< Metres the obstacle distances and the goal are given as fractions of.
  const LaserRays* scan = nullptr;  ///< Its laser, in its own frame (~obstacles scan or rays).
  const GridMap* map = nullptr;     ///< Its map (~obstacles memory), seen from `robot`.
  MapPoint robot;                   ///< Map-frame metres (memory only).
};

/// mrpt_reactive_node's steering, without ROS: obstacle distances per sector for the robot's body (~obstacles,
/// ~robot_radius), counted in the robot's frame or the goal's (~frame), the holonomic method's choice (~method),
/// and the velocity it makes (~kinematics, ~max_speed, ~max_turn).
class ReactiveSteering {
 public:
  /// @throws InvalidArgument naming the parameter out of its range or choices.
  explicit ReactiveSteering(const ReactiveNodeParameters& parameters);

  /// Starts an episode with a new method object (ND remembers the direction it chose last).
  void reset() { navigator_.reset(); }
  /// The command for `view`; NaN rays of its scan are counted in `*invalid_rays`.
  /// @throws InvalidArgument naming goal (not finite), scan (rays placed nowhere) or map (none given for memory).
  BodyVelocity command(const ReactiveView& view, int* invalid_rays);
  /// The method's choice for `view`, its direction in the robot's frame. @throws as command().
  Heading steer(const ReactiveView& view, int* invalid_rays);

 private:
  ReactiveNodeParameters parameters_;
  MrptReactiveNavigator navigator_;
};

}  // namespace planners
}  // namespace ppp
