#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ppp_core/map_frame.hpp"
#include "sector_obstacles.hpp"

namespace mrpt::nav {
class CAbstractHolonomicReactiveMethod;
class ClearanceDiagram;
}  // namespace mrpt::nav

namespace ppp {
namespace planners {

/// MRPT's holonomic reactive methods by the names `~method` takes: Nearness Diagram, virtual force field, and
/// full evaluation of every direction.
const std::vector<std::string>& reactiveMethodNames();

/// What a holonomic method chose: a direction in the frame its sectors were given in (radians in [-π, π], 0 along
/// its x axis, counter-clockwise) and a speed as a fraction of the robot's top speed, in [0, 1].
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

}  // namespace planners
}  // namespace ppp
