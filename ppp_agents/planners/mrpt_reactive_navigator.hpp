#pragma once

#include <memory>
#include <string>
#include <vector>

#include "grid_map.hpp"
#include "ppp_core/map_frame.hpp"

namespace mrpt::nav {
class CAbstractHolonomicReactiveMethod;
class ClearanceDiagram;
}  // namespace mrpt::nav

namespace ppp {
namespace planners {

/// MRPT's holonomic reactive methods by the names `~method` takes: Nearness Diagram, virtual force field, and
/// full evaluation of every direction.
const std::vector<std::string>& reactiveMethodNames();

/// The directions obstacles are given in: sector k is centred at -π + (k + ½)·2π/kReactiveSectors in the map frame
/// (MRPT's holonomic convention: the first sector points backwards, counter-clockwise from there).
constexpr int kReactiveSectors = 72;

/// What a holonomic method chose: a direction in the map frame (radians in [-π, π], 0 east, counter-clockwise)
/// and a speed as a fraction of the robot's top speed, in [0, 1].
struct Heading {
  double direction = 0;
  double speed = 0;
};

/// One of MRPT's holonomic reactive navigators (mrpt::nav::CHolonomicND, CHolonomicVFF, CHolonomicFullEval) with
/// their default options, driven as its reactive navigation drives them: distances to obstacles per direction and
/// the target, both as fractions of one sensing range, in; a direction and a speed out. The robot is holonomic
/// and its frame stays aligned with the map's, so directions are map-frame angles.
class MrptReactiveNavigator {
 public:
  /// @throws InvalidArgument naming method when `method` is none of reactiveMethodNames().
  explicit MrptReactiveNavigator(const std::string& method);
  ~MrptReactiveNavigator();

  /// Starts an episode with a new method object (ND prefers the direction it chose last).
  void reset();
  /// The method's choice for `obstacles` (kReactiveSectors distances, 1 where nothing is within range) and
  /// `target` (the goal relative to the robot), both in fractions of the sensing range.
  /// @throws InvalidArgument naming obstacles when there are not kReactiveSectors of them in [0, 1].
  Heading navigate(const std::vector<double>& obstacles, MapPoint target);

 private:
  std::string method_;
  std::shared_ptr<mrpt::nav::CAbstractHolonomicReactiveMethod> navigator_;
  std::unique_ptr<mrpt::nav::ClearanceDiagram> clearance_;  // FullEval asks for one; none of them reads it
};

/// A laser scan as sensor_msgs/LaserScan gives it, in the robot's frame (aligned with the map's).
struct LaserRays {
  double angle_min = 0;        ///< Radians of the first ray, counter-clockwise from east.
  double angle_increment = 0;  ///< Radians between rays.
  std::vector<float> ranges;   ///< Metres; +inf: no return within range, NaN: no valid reading.
};

/// Distances to obstacles per sector, as fractions of `range` metres (1: nothing nearer): the nearest ray that
/// lies in a sector (a ray on the border of two counts for both); a sector no ray falls in sees nothing. A ray
/// that is NaN is taken as an obstacle touching the robot (0) and counted in `*invalid_rays`.
std::vector<double> sectorObstacles(const LaserRays& scan, double range, int* invalid_rays);

/// Distances to obstacles per sector as fractions of `range` metres, cast from `from` on what `map` knows: each
/// sector's centre ray ends at the first cell that is not passable (an obstacle, or off the map).
std::vector<double> sectorObstaclesInMap(const GridMap& map, MapPoint from, double range);

}  // namespace planners
}  // namespace ppp
