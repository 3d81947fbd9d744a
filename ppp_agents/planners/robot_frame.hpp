#pragma once

#include <cmath>

#include "ppp_core/map_frame.hpp"

namespace ppp {
namespace planners {

/// A map-frame displacement `offset` (east, north) in the frame of a robot heading `heading` radians
/// counter-clockwise from east (x ahead, y to its left): what a local planner compares its scan's directions with.
inline MapPoint inRobotFrame(MapPoint offset, double heading) {
  const double c = std::cos(heading), s = std::sin(heading);
  return MapPoint{c * offset.x + s * offset.y, -s * offset.x + c * offset.y};
}

}  // namespace planners
}  // namespace ppp
