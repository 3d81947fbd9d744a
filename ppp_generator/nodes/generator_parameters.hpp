#pragma once

#include <string>

#include <ros/node_handle.h>

#include "ppp_core/episode_options.hpp"
#include "ppp_generator/generator_options.hpp"
#include "ppp_generator/generator_node_options.hpp"

namespace ppp {
namespace generator {

/// What the generator node reads from its private (`~`) parameters: its own (declared) and the generator options.
struct NodeParameters : GeneratorNodeOptions {
  GeneratorOptions options;  ///< The generator's options (defaults: config/generator.yaml's).
  EpisodeOptions episode;    ///< The rules of a panel fitness's episodes when it hunts in process (~evaluator '').
};

/// Reads and validates the `~` parameters: the generator options from `~options` (YAML text as in
/// config/generator.yaml) when given, then from the single `~` parameters of the same names. @throws InvalidArgument naming the parameter ("~population").
NodeParameters readNodeParameters(const ros::NodeHandle& private_nh);

}  // namespace generator
}  // namespace ppp
