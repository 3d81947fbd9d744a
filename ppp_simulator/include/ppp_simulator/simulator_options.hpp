#pragma once

#include <vector>

#include "ppp_core/option_spec.hpp"

namespace ppp {
namespace simulator {

/// How the simulator node plays an experiment with agent nodes: message batching, timeouts and recording. Read
/// by the node as `~` parameters; `ppp launch-file` (and so launch/experiment.launch) takes each as a flag.
struct SimulatorOptions {
  int batch_size = 2000;                ///< Episodes per agent per message.
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

}  // namespace simulator
}  // namespace ppp
