#pragma once

#include <functional>
#include <string>

#include <ros/ros.h>

#include "ppp_generator/fitness.hpp"
#include "ppp_generator/generator_options.hpp"

namespace ppp {
namespace generator {

/// The panel fitness (failure or regret) of a hunt through ROS: each batch of candidate PPPs goes to the simulator
/// node's `service` (ppp_msgs/EvaluateProblems) with the panel options.agents, options.runs_per_eval runs and the
/// generator seed, and comes back as failure rates and regrets; scores by panelScore(), batches of the options' round_size,
/// so built-in agents give the set an in-process hunt gives. Waits up to `wait_seconds` for the service.
/// @throws IoError when the service does not come, a call fails or the simulator refuses the request (its
/// message, naming the field, is passed on); Interrupted when a call fails once `stopping` says the node stops.
Fitness makeRemoteFailureFitness(ros::NodeHandle& nh, const GeneratorOptions& options, const std::string& service,
                                 double wait_seconds, const std::function<bool()>& stopping);

}  // namespace generator
}  // namespace ppp
