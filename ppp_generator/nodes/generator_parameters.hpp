#pragma once

#include <string>

#include <ros/node_handle.h>

#include "ppp_generator/generator_options.hpp"
#include "ppp_msgs/topic_names.h"

namespace ppp {
namespace generator {

/// What the generator node reads from its private (`~`) parameters besides the generator options.
struct NodeParameters {
  GeneratorOptions options;     ///< The generator's options (defaults: config/generator.yaml's).
  std::string set_name;         ///< Name of the published set ("": the fitness name).
  std::string output_dir;       ///< When set, the set's files are written here, as `ppp generate -o` does.
  bool resume = false;          ///< When output_dir already holds the set of these options, publish it as is.
  int publish_index = 0;        ///< Which PPP of the set is published on `map`.
  double resolution = 1.0;      ///< Metres per cell of the published maps.
  bool generate_on_start = true;  ///< Evolve a set at start-up (otherwise only on the service call).
  bool exit_when_done = false;    ///< Exit once the start-up set is published.
  std::string evaluator = ppp_msgs::topics::kEvaluator;  ///< Failure fitness: the simulator's EvaluateProblems service.
  double evaluator_timeout = 120.0;  ///< Seconds to wait for that service to appear.
};

/// Reads and validates the `~` parameters: the generator options from `~options` (YAML text as in
/// config/generator.yaml) when given, then from the single `~` parameters of the same names. @throws InvalidArgument naming the parameter ("~population").
NodeParameters readNodeParameters(const ros::NodeHandle& private_nh);

}  // namespace generator
}  // namespace ppp
