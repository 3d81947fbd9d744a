#pragma once

#include <string>
#include <vector>

#include "ppp_msgs/launch_graph.h"
#include "ppp_simulator/experiment_config.hpp"
#include "ppp_simulator/simulator_options.hpp"

namespace ppp {
namespace simulator {

/// What the ROS graph of an experiment needs beyond its config: where things are and the simulator's pace.
struct GraphOptions {
  std::string config_path;      ///< The experiment YAML, absolute (the simulator reads it).
  std::string output_dir;       ///< The output directory, absolute.
  SimulatorOptions simulator;   ///< The simulator node's options, passed as its parameters.
  /// When set, the graph of a hunt instead: only this `failure` set of the config is evolved, into OUTPUT_DIR.
  std::string hunt;
  /// The env-loader script remote machines run nodes through (the workspace's devel/env.sh at the same path).
  std::string env_loader;
  /// @throws InvalidArgument naming the option.
  void validate(const ExperimentConfig& config) const;
};

/// Sets planner agent `agent`'s planner_node ("package/executable", or "" for a planner the user starts), as a
/// command line may override the config's. @throws InvalidArgument naming "planner" for an unknown planner agent.
void assignPlannerNode(ExperimentConfig* config, const std::string& agent, const std::string& planner_node);

/// The generator node that evolves set `set_name` ("gen_" + its name as a ROS name).
std::string generatorNodeName(const std::string& set_name);

/// The latched topic the generator node of `set_name` publishes the set on ("/gen_NAME/problem_set").
std::string setTopic(const std::string& set_name);

/// The ROS graph of `config`'s experiment, and nothing else (render it with ppp_msgs::launchXml or launchJson): one generator_node per evolved set (options
/// from the config, resuming a set already written), the simulator_node (required; it plays the sets the
/// generator nodes publish), one agent_node per built-in agent and a planner_bridge_node (plus the planner
/// when one is named) per planner agent, each on its agent's host. With `options.hunt`, the graph of that
/// set's hunt: its generator node (required, writing OUTPUT_DIR), the simulator serving hunts, and the nodes of
/// the panel's agents only. @throws InvalidArgument.
ppp_msgs::LaunchGraph experimentGraph(const ExperimentConfig& config, const GraphOptions& options);

}  // namespace simulator
}  // namespace ppp
