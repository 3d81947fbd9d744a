#pragma once

#include <string>

#include <ros/node_handle.h>

#include "ppp_simulator/simulator_options.hpp"

namespace ppp {
namespace simulator {

/// The simulator node's `~` parameters: what to run, and how (both declared).
struct SimulatorParameters : SimulatorOptions, SimulatorTask {};

/// Reads and checks the parameters. @throws InvalidArgument naming the parameter ("~batch_size").
SimulatorParameters readSimulatorParameters(const ros::NodeHandle& private_nh);

}  // namespace simulator
}  // namespace ppp
