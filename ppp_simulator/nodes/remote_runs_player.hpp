#pragma once

#include <string>

#include <ros/ros.h>

#include "ppp_core/episode_options.hpp"
#include "ppp_simulator/failure_shrink.hpp"

namespace ppp {
namespace simulator {

/// A shrink's runs played through the simulator node's `service` (ppp_msgs/EvaluateProblems, ~mode hunt): each
/// candidate goes there alone with `agent` and the judged seeds as its run seeds, and its failures come back
/// diagnosed, so any agent of the experiment (a planner node included) is judged exactly as in an experiment. A
/// PPP the robot cannot solve under `episode` is judged invalid here, without a call. Waits up to `wait_seconds`
/// for the service. @throws IoError when it does not come; the player throws IoError when a call fails, the
/// simulator refuses it (its message passed on) or the agent can no longer play (leavesAgentUnreachable()),
/// Interrupted when ROS shuts down.
RunsPlayer remoteRunsPlayer(ros::NodeHandle& nh, const std::string& service, const std::string& agent,
                            const EpisodeOptions& episode, double wait_seconds);

}  // namespace simulator
}  // namespace ppp
