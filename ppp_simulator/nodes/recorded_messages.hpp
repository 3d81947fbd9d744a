#pragma once

// The messages the episode recorder publishes and writes to the bag that are not standard conversions.

#include <visualization_msgs/MarkerArray.h>

#include "ppp_agents/episode_result.hpp"
#include "ppp_core/map_frame.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_msgs/EpisodeResult.h"

namespace ppp {
namespace simulator {

/// A green cube on the start cell of `problem` and a red one on its goal, in frame `map`, as rviz draws markers.
visualization_msgs::MarkerArray startAndGoalMarkers(const MapFrame& frame, const Problem& problem);

/// A results.csv row as the message /ppp/results carries.
ppp_msgs::EpisodeResult resultMessage(const agents::EpisodeResult& row);

}  // namespace simulator
}  // namespace ppp
