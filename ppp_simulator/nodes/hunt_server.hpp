#pragma once

#include <ros/ros.h>

#include "simulator_parameters.hpp"

namespace ppp {
namespace simulator {

/// The simulator node in hunt mode: serves ~evaluate (ppp_msgs/EvaluateProblems) until shut down. Each
/// request's PPPs are played by the named agents of ~config (agent nodes on /NAME/scans and /NAME/moves,
/// planner bridges, exactly as in an experiment), `runs` times each, seeded as the in-process failure fitness
/// does; the answer says per PPP how often the panel failed and why. Agents that time out or die fail their
/// runs with that reason, so a hunt never hangs on them. Returns the exit status.
int runHuntServer(ros::NodeHandle& nh, ros::NodeHandle& private_nh, const SimulatorParameters& parameters);

}  // namespace simulator
}  // namespace ppp
