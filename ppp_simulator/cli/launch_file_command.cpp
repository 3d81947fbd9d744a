#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ppp_core/error.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_simulator/experiment_graph.hpp"
#include "ppp_simulator/experiment_runner.hpp"

namespace ppp {
namespace cli {

namespace {

struct LaunchFileFlags {
  std::string config;
  std::string output;
  simulator::GraphOptions graph;
  std::vector<std::string> planners;
};

/// "NAME=PACKAGE/EXECUTABLE" as a planner node. @throws InvalidArgument naming --planner.
simulator::PlannerNode parsePlanner(const std::string& text) {
  const std::size_t equals = text.find('=');
  const std::size_t slash = text.find('/', equals == std::string::npos ? 0 : equals);
  if (equals == std::string::npos || equals == 0) {
    throw InvalidArgument("--planner", "expected NAME=PACKAGE/EXECUTABLE or NAME=, got '" + text + "'");
  }
  simulator::PlannerNode node{text.substr(0, equals), "", ""};
  if (equals + 1 == text.size()) return node;  // NAME=: the user starts the planner
  if (slash == std::string::npos || slash == equals + 1 || slash + 1 == text.size()) {
    throw InvalidArgument("--planner", "expected NAME=PACKAGE/EXECUTABLE or NAME=, got '" + text + "'");
  }
  node.package = text.substr(equals + 1, slash - equals - 1);
  node.type = text.substr(slash + 1);
  return node;
}

void runLaunchFile(LaunchFileFlags flags) {
  namespace fs = std::filesystem;
  const simulator::ExperimentConfig config = simulator::loadExperimentConfig(flags.config);
  flags.graph.config_path = fs::absolute(flags.config).lexically_normal().string();
  flags.graph.output_dir = fs::absolute(flags.output).lexically_normal().string();
  for (const std::string& p : flags.planners) flags.graph.planners.push_back(parsePlanner(p));
  if (flags.graph.hunt.empty()) simulator::checkExperimentDirectory(config, flags.graph.output_dir);
  if (!flags.graph.hunt.empty()) generator::checkOutputDirectory(flags.graph.output_dir);
  std::cout << simulator::experimentLaunchXml(config, flags.graph);
}

}  // namespace

void addLaunchFileCommand(CLI::App& app) {
  auto flags = std::make_shared<LaunchFileFlags>();
  CLI::App* command = app.add_subcommand(
      "launch-file", "Write the roslaunch XML that runs an experiment through ROS (what launch/experiment.launch runs)");
  command->add_option("config", flags->config, "Experiment YAML (e.g. config/experiment.yaml)")->required();
  command->add_option("-o,--output", flags->output, "The experiment's output directory")->required();
  command->add_option("--batch-size", flags->graph.batch_size, "Episodes per agent per message")
      ->capture_default_str();
  command->add_option("--step-timeout", flags->graph.step_timeout, "Seconds an agent node has to answer a batch")
      ->capture_default_str();
  command->add_option("--record", flags->graph.record, "Write OUTPUT/experiment.bag (true or false)")
      ->capture_default_str();
  command->add_option("--planner", flags->planners,
                      "NAME=PACKAGE/EXECUTABLE: start this planner for planner agent NAME (NAME=: start none, the "
                      "user runs it in /NAME/robot); overrides the agent's planner_node");
  command->add_option("--hunt", flags->graph.hunt,
                      "SET: the graph of hunting this failure set of the config into OUTPUT instead (panel agents only)");
  command->add_option("--env-loader", flags->graph.env_loader,
                      "Script remote machines run nodes through (the workspace's devel/env.sh, same path there)");
  command->callback([flags] { runLaunchFile(*flags); });
}

}  // namespace cli
}  // namespace ppp
