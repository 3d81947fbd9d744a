#pragma once

#include <string>
#include <vector>

#include <nav_msgs/Path.h>

#include "ppp_agents/planner_episode.hpp"

namespace ppp {
namespace agents {

/// A frame name without a leading slash (tf2 frames have none).
std::string bareFrame(const std::string& frame);

/// Turns a planner's path into map points, checking that it and each pose are in `map_frame` (a pose may leave
/// its frame empty) and every point is finite. Returns "" or what is wrong.
std::string pathPoints(const nav_msgs::Path& path, const std::string& map_frame, std::vector<MapPoint>* points);

}  // namespace agents
}  // namespace ppp
