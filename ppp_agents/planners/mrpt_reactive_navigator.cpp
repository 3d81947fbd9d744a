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

/// Radians per sector.
constexpr double kSectorWidth = 2 * M_PI / kReactiveSectors;

/// The map-frame angle of sector k's centre.
double sectorAngle(int k) { return -M_PI + (k + 0.5) * kSectorWidth; }

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

std::vector<double> sectorObstacles(const LaserRays& scan, double range, int* invalid_rays) {
  std::vector<double> obstacles(kReactiveSectors, 1.0);
  *invalid_rays = 0;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    double distance = scan.ranges[i];
    if (std::isnan(distance)) {
      ++*invalid_rays;
      distance = 0;
    }
    const double fraction = std::clamp(distance / range, 0.0, 1.0);
    // The ray's place among the sectors, from the backward direction -π counter-clockwise.
    const double angle = std::remainder(scan.angle_min + i * scan.angle_increment, 2 * M_PI);  // in [-π, π]
    const double place = (angle + M_PI) / kSectorWidth;
    const int sector = static_cast<int>(std::floor(place)) % kReactiveSectors;
    obstacles[sector] = std::min(obstacles[sector], fraction);
    const double offset = place - std::floor(place);
    // A ray this close to a border (in sector widths) lies on it. LaserScan's angles are floats: its rays come
    // out up to 2e-6 sector widths off the borders they lie on, so a tighter tolerance would put them in one
    // sector only, and a planner would see another scan through ROS than the same rays in double precision.
    constexpr double kBorder = 1e-3;
    if (offset < kBorder) {
      const int before = (sector + kReactiveSectors - 1) % kReactiveSectors;
      obstacles[before] = std::min(obstacles[before], fraction);
    } else if (offset > 1 - kBorder) {
      const int after = (sector + 1) % kReactiveSectors;
      obstacles[after] = std::min(obstacles[after], fraction);
    }
  }
  return obstacles;
}

std::vector<double> sectorObstaclesInMap(const GridMap& map, MapPoint from, double range) {
  std::vector<double> obstacles(kReactiveSectors, 1.0);
  const double step = map.frame().resolution / 8;
  for (int k = 0; k < kReactiveSectors; ++k) {
    const double east = std::cos(sectorAngle(k));
    const double north = std::sin(sectorAngle(k));
    for (double t = step; t <= range; t += step) {
      if (!map.passable(map.cellOf(MapPoint{from.x + east * t, from.y + north * t}))) {
        obstacles[k] = t / range;
        break;
      }
    }
  }
  return obstacles;
}

}  // namespace planners
}  // namespace ppp
