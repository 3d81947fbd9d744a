#include "mrpt_reactive_navigator.hpp"

#include <mrpt/nav/holonomic/CAbstractHolonomicReactiveMethod.h>
#include <mrpt/nav/holonomic/ClearanceDiagram.h>

#include <algorithm>
#include <cmath>
#include <exception>

#include "ppp_core/error.hpp"

namespace ppp {
namespace planners {

namespace {

/// MRPT's class name of a method name.
std::string className(const std::string& method) { return "CHolonomic" + method; }

}  // namespace

const std::vector<std::string>& reactiveMethodNames() {
  static const std::vector<std::string> names = {"ND", "VFF", "FullEval"};
  return names;
}

MrptReactiveNavigator::MrptReactiveNavigator(const std::string& method)
    : method_(method), clearance_(std::make_unique<mrpt::nav::ClearanceDiagram>()) {
  const std::vector<std::string>& names = reactiveMethodNames();
  if (std::find(names.begin(), names.end(), method) == names.end()) {
    throw InvalidArgument("method", "unknown holonomic method '" + method + "'; valid: ND, VFF, FullEval");
  }
  reset();
}

MrptReactiveNavigator::~MrptReactiveNavigator() = default;

void MrptReactiveNavigator::reset() {
  navigator_ = mrpt::nav::CAbstractHolonomicReactiveMethod::Factory(className(method_));
  if (!navigator_) throw Error("MRPT has no holonomic method " + className(method_));
}

Heading MrptReactiveNavigator::navigate(const std::vector<double>& obstacles, MapPoint target) {
  if (obstacles.size() != static_cast<std::size_t>(kReactiveSectors)) {
    throw InvalidArgument("obstacles", "expected " + std::to_string(kReactiveSectors) + " sectors, got " +
                                           std::to_string(obstacles.size()));
  }
  for (const double d : obstacles) {
    if (!(d >= 0 && d <= 1)) throw InvalidArgument("obstacles", "expected fractions of the range in [0, 1]");
  }
  mrpt::nav::CAbstractHolonomicReactiveMethod::NavInput input;
  input.obstacles = obstacles;
  input.targets = {mrpt::math::TPoint2D(target.x, target.y)};
  input.maxRobotSpeed = 1.0;
  input.maxObstacleDist = 1.0;
  input.clearance = clearance_.get();
  mrpt::nav::CAbstractHolonomicReactiveMethod::NavOutput output;
  try {
    navigator_->navigate(input, output);
  } catch (const std::exception& e) {
    throw Error("MRPT " + className(method_) + ": " + e.what());
  }
  return Heading{output.desiredDirection, std::clamp(output.desiredSpeed, 0.0, 1.0)};
}

}  // namespace planners
}  // namespace ppp
