#pragma once

#include <string>
#include <vector>

#include "ppp_msgs/launch_graph.h"
#include "ppp_simulator/corpus_check.hpp"
#include "ppp_simulator/experiment_config.hpp"
#include "ppp_simulator/shrink_job.hpp"
#include "ppp_simulator/simulator_options.hpp"

namespace ppp {
namespace simulator {

/// What the ROS graph of an experiment needs beyond its config: where things are and the simulator's pace.
struct GraphOptions {
  std::string config_path;      ///< The experiment YAML, absolute (the simulator reads it).
  std::string output_dir;       ///< The output directory, absolute.
  SimulatorOptions simulator;   ///< The simulator node's options, passed as its parameters.
  /// When set, the graph of a hunt instead: only this set of the config, evolved with a panel fitness (failure
  /// or regret), is evolved, into OUTPUT_DIR.
  std::string hunt;
  /// When its input is set, the graph of a shrink instead: the shrink node (required) judging its candidates
  /// through the simulator serving hunts, which plays them on the nodes of `shrink.agent` only.
  ShrinkTask shrink;
  /// When its corpus is set, the graph of a check instead: the check node (required) playing every PPP of the
  /// corpus through the simulator serving hunts, on the nodes of `check.agent` only.
  CheckTask check;
  /// The env-loader script remote machines run nodes through (the workspace's devel/env.sh at the same path).
  std::string env_loader;
  /// The planner nodes assigned over the config file's (assignPlanners), which the config given to experimentGraph
  /// holds already: passed on to the simulator, which reads the file, so that it expects the instances the graph
  /// starts.
  std::vector<std::string> planners;
  /// agents::kProcessManager: the simulator, the generator nodes and the agent nodes of agents with `process:
  /// manager` on this host run as nodelets in one nodelet manager (which the graph then requires: it ends with
  /// the simulator's experiment, a hunt's set or the shrink); agents::kProcessOwn: every node in a process of its
  /// own. Planner bridges and planners always run in processes of their own.
  std::string processes = agents::kProcessManager;
  /// @throws InvalidArgument naming the option.
  void validate(const ExperimentConfig& config) const;
};

/// Sets the planner_node of the planner agents named in `assignments` ("NAME=PACKAGE/EXECUTABLE", or "NAME=" for a
/// planner the user starts), as a launch may override the config's. @throws InvalidArgument naming "planner" for a
/// malformed assignment or an unknown planner agent, or the planner_node's problem.
void assignPlanners(ExperimentConfig* config, const std::vector<std::string>& assignments);

/// The experiment config as a launched graph runs it: `task.config` with `task.planners` assigned.
/// @throws ParseError, IoError or InvalidArgument as loadExperimentConfig and assignPlanners.
ExperimentConfig launchedConfig(const SimulatorTask& task);

/// The generator node that evolves set `set_name` ("gen_" + its name as a ROS name).
std::string generatorNodeName(const std::string& set_name);

/// The latched topic the generator node of `set_name` publishes the set on ("/gen_NAME/problem_set").
std::string setTopic(const std::string& set_name);

/// The ROS graph of `config`'s experiment, and nothing else (render it with ppp_msgs::launchXml or launchJson): one generator_node per evolved set (options
/// from the config, resuming a set already written), the simulator_node (required; it plays the sets the
/// generator nodes publish), one agent_node per built-in agent and a planner_bridge_node (plus the planner
/// when one is named) per planner agent, each on its agent's host. With `options.hunt`, the graph of that
/// set's hunt: its generator node (required, writing OUTPUT_DIR), the simulator serving hunts, and the nodes of
/// the panel's agents only; with `options.shrink`, the graph of that shrink (its agent's nodes only).
/// @throws InvalidArgument.
ppp_msgs::LaunchGraph experimentGraph(const ExperimentConfig& config, const GraphOptions& options);

}  // namespace simulator
}  // namespace ppp
