#pragma once

#include <string>

#include <ros/node_handle.h>

#include "ppp_simulator/simulator_options.hpp"

namespace ppp {
namespace simulator {

/// ~mode: run the experiment of ~config (the default).
constexpr const char* kExperimentMode = "experiment";
/// ~mode: serve ~evaluate, playing a hunt's candidate PPPs with ~config's agents, until shut down.
constexpr const char* kHuntMode = "hunt";

/// The simulator node's `~` parameters: what to run, and how (the declared SimulatorOptions).
struct SimulatorParameters : SimulatorOptions {
  std::string mode = kExperimentMode;       ///< kExperimentMode or kHuntMode.
  std::string config;                       ///< Experiment YAML (required), as for `ppp experiment`.
  std::string output_dir;                   ///< Output directory (required for an experiment); rerun to resume.
  /// Play the evolved sets the generator nodes publish (setTopic() of each set, as launch/experiment.launch starts
  /// them) instead of evolving them here; sets given as directories are read from disk either way.
  bool generator_nodes = false;
};

/// Reads and checks the parameters. @throws InvalidArgument naming the parameter ("~batch_size").
SimulatorParameters readSimulatorParameters(const ros::NodeHandle& private_nh);

}  // namespace simulator
}  // namespace ppp
