#pragma once

#include <cstdint>
#include <vector>

namespace ppp {

/// Turns a scan window into laser ranges, for tools that expect a range sensor (sensor_msgs/LaserScan).
/// Ray i points at angle 2*pi*i/rays, counter-clockwise from the +x axis of the ROS map frame (east, with north
/// = grid row - 1). Each ray is marched from the agent's cell centre in steps of 1/20 cell; it ends at the first
/// obstacle or out-of-bounds cell (range to that point, in cells) or, reaching an unknown cell or the window's
/// edge, reports infinity (no return).
std::vector<float> windowRanges(const std::int8_t* cells, int range, int rays);

}  // namespace ppp
