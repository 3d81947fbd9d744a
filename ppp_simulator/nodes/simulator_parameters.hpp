#pragma once

#include <string>

#include <ros/node_handle.h>

namespace ppp {
namespace simulator {

/// ~mode: run the experiment of ~config (the default).
constexpr const char* kExperimentMode = "experiment";
/// ~mode: serve ~evaluate, playing a hunt's candidate PPPs with ~config's agents, until shut down.
constexpr const char* kHuntMode = "hunt";

/// The simulator node's `~` parameters.
struct SimulatorParameters {
  std::string mode = kExperimentMode;       ///< kExperimentMode or kHuntMode.
  std::string config;                       ///< Experiment YAML (required), as for `ppp experiment`.
  std::string output_dir;                   ///< Output directory (required for an experiment); rerun to resume.
  int batch_size = 2000;                    ///< Episodes per agent per message, >= 1.
  double step_timeout = 5.0;                ///< Seconds an agent has to answer a batch.
  double planner_step_timeout = 30.0;       ///< Seconds a planner agent's bridge has to answer a step.
  int timeouts_before_giving_up = 3;        ///< Consecutive unanswered batches after which an agent's runs all fail.
  double connect_timeout = 60.0;            ///< Seconds to wait for each agent node to connect.
  /// Play the evolved sets the generator nodes publish (setTopic() of each set, as launch/experiment.launch starts
  /// them) instead of evolving them here; sets given as directories are read from disk either way.
  bool generator_nodes = false;
  double set_timeout = 60.0;                ///< Seconds a set's topic may go without a publisher before giving up.
  bool record = true;                       ///< Write <output_dir>/experiment.bag.
  int record_runs = 1;                      ///< Runs 0 .. record_runs-1 of ...
  int record_problems = 1;                  ///< ... the first record_problems PPPs of each set are recorded in detail.
  double resolution = 1.0;                  ///< Metres per cell in the map frame.
};

/// Reads and checks the parameters. @throws InvalidArgument naming the parameter ("~batch_size").
SimulatorParameters readSimulatorParameters(const ros::NodeHandle& private_nh);

}  // namespace simulator
}  // namespace ppp
