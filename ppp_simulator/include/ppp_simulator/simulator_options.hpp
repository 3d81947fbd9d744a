#pragma once

#include <string>
#include <vector>

#include "ppp_core/option_spec.hpp"

namespace ppp {
namespace simulator {

/// The batch size of `ppp launch-file`'s graph in one nodelet manager unless given: a built-in agent there answers
/// in its lane's thread (no round trip to amortise), and the episodes of fewer batches in flight stay in cache.
constexpr int kManagerBatchSize = 500;

/// How the simulator node plays an experiment with agent nodes: message batching, timeouts and recording. Read
/// by the node as `~` parameters; `ppp launch-file` (and so launch/experiment.launch) takes each as a flag.
struct SimulatorOptions {
  int batch_size = 2000;                ///< Episodes per agent per message (kManagerBatchSize in one manager).
  double step_timeout = 5.0;            ///< Seconds an agent node has to answer a batch.
  double planner_step_timeout = 30.0;   ///< Seconds a planner agent's bridge has to answer a step.
  int timeouts_before_giving_up = 3;    ///< Consecutive unanswered batches after which an agent's runs all fail.
  double connect_timeout = 60.0;        ///< Seconds to wait for each agent node to connect.
  double set_timeout = 60.0;            ///< Seconds a set's topic may go without a publisher before giving up.
  bool record = true;                   ///< Write <output_dir>/experiment.bag.
  int record_runs = 1;                  ///< Runs 0 .. record_runs-1 of ...
  int record_problems = 1;              ///< ... the first record_problems PPPs of each set are recorded in detail.
  double resolution = 1.0;              ///< Metres per cell in the map frame.
  /// @throws InvalidArgument naming the option out of its declared range.
  void validate() const;
};

/// One declaration per simulator option (the node's `~` parameters, `ppp launch-file` flags).
const std::vector<OptionSpec<SimulatorOptions>>& simulatorOptionSpecs();

/// ~mode: run the experiment of ~config (the default).
constexpr const char* kExperimentMode = "experiment";
/// ~mode: serve ~evaluate, playing a hunt's candidate PPPs with ~config's agents, until shut down.
constexpr const char* kHuntMode = "hunt";

/// What the simulator node runs: its `~` parameters besides SimulatorOptions, which the experiment's graph sets.
struct SimulatorTask {
  std::string mode = kExperimentMode;  ///< kExperimentMode or kHuntMode.
  std::string config;                  ///< Experiment YAML (required), as for `ppp experiment`.
  std::string output_dir;              ///< Output directory (required for an experiment); rerun to resume.
  /// Play the evolved sets the generator nodes publish (setTopic() of each set, as launch/experiment.launch starts
  /// them) instead of evolving them here; sets given as directories are read from disk either way.
  bool generator_nodes = false;
  /// Planner nodes assigned at launch over the config's planner_node ("NAME=PACKAGE/EXECUTABLE", or "NAME=" for
  /// one the user starts), as `ppp launch-file --planner` gives them: they decide how many instances play.
  std::vector<std::string> planners;
};

/// One declaration per SimulatorTask parameter.
const std::vector<OptionSpec<SimulatorTask>>& simulatorTaskSpecs();

}  // namespace simulator
}  // namespace ppp
