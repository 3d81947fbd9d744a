#pragma once

#include <string>
#include <vector>

#include "ppp_core/option_spec.hpp"
#include "ppp_msgs/graph_names.h"

namespace ppp {
namespace generator {

/// The generator node's `~` parameters besides the generator options themselves: what it publishes and writes.
struct GeneratorNodeOptions {
  std::string options_yaml;       ///< `~options`: generator options as YAML text; single `~` parameters override it.
  std::string set_name;           ///< Name of the published set ("": the fitness name).
  std::string output_dir;         ///< When set, the set's files are written here, as `ppp generate -o` does.
  bool resume = false;            ///< When output_dir already holds the set of these options, publish it as is.
  int publish_index = 0;          ///< Which PPP of the set is published on `map`.
  double resolution = 1.0;        ///< Metres per cell of the published maps.
  bool generate_on_start = true;  ///< Evolve a set at start-up (otherwise only on the service call).
  bool exit_when_done = false;    ///< Exit once the start-up set is published.
  std::string evaluator = ppp_msgs::topics::kEvaluator;  ///< Failure fitness: the simulator's EvaluateProblems service.
  double evaluator_timeout = 120.0;                      ///< Seconds to wait for that service to appear.
  std::string wait_for_set;       ///< A set topic to hear from before evolving (its set is the initial pool).
  /// @throws InvalidArgument naming the option out of its declared range.
  void validate() const;
};

/// One declaration per generator node parameter (the node reads them; the experiment's graph writes them).
const std::vector<OptionSpec<GeneratorNodeOptions>>& generatorNodeOptionSpecs();

}  // namespace generator
}  // namespace ppp
