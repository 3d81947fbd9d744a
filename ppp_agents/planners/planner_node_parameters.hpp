#pragma once

#include <ros/node_handle.h>

#include <cstdint>
#include <string>

#include "ompl_grid_planner.hpp"

namespace ppp {
namespace planners {

/// The tf frames a planner node plans in.
struct PlannerFrames {
  std::string map_frame = "map";  ///< Frame of the map, the goal and the plan.
  std::string base_frame;         ///< The robot's frame; its origin is the robot's position.
};

/// What the OMPL planner node reads besides its frames.
struct OmplNodeParameters {
  OmplPlannerOptions planner;   ///< ~planner and ~planning_time.
  std::uint32_t seed = 1;       ///< ~seed, for ompl::RNG::setSeed.
  bool unknown_is_free = true;  ///< ~unknown_is_free: plan through unknown map cells.
};

/// The default ~base_frame of a node in `node_namespace`: the namespace without its leading slash, then
/// "/base_link" ("/ompl/robot" -> "ompl/robot/base_link", "/" -> "base_link").
std::string defaultBaseFrame(const std::string& node_namespace);

/// Reads ~map_frame (default "map") and ~base_frame (default defaultBaseFrame(node_namespace)).
/// @throws InvalidArgument naming the parameter when it is not a non-empty tf frame name (no leading slash).
PlannerFrames readPlannerFrames(const ros::NodeHandle& private_nh, const std::string& node_namespace);

/// Reads ~planner (default RRTConnect), ~planning_time (1.0 s), ~seed (1; an int in [1, 2^31 - 1]) and
/// ~unknown_is_free (true). @throws InvalidArgument naming the parameter and what was expected.
OmplNodeParameters readOmplNodeParameters(const ros::NodeHandle& private_nh);

}  // namespace planners
}  // namespace ppp
