#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "option_flags.hpp"
#include "ppp_core/error.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_simulator/experiment_graph.hpp"
#include "ppp_simulator/experiment_runner.hpp"
#include "ppp_simulator/hunt_corpus.hpp"

namespace ppp {
namespace cli {

namespace {

struct LaunchFileFlags {
  CLI::App* command = nullptr;
  std::string config;
  std::string output;
  simulator::GraphOptions graph;
  std::map<std::string, std::string> simulator_flags;
  std::map<std::string, std::string> shrink_flags;
  std::map<std::string, std::string> check_flags;
  bool large = false;
  bool json = false;
};

/// The shrink's options `ppp launch-file` takes as flags (--shrink INPUT, --agent NAME, --runs N, ...); the config
/// and the output are its own.
const std::vector<OptionSpec<simulator::ShrinkTask>>& shrinkFlagSpecs() {
  static const std::vector<OptionSpec<simulator::ShrinkTask>> specs = [] {
    std::vector<OptionSpec<simulator::ShrinkTask>> list = selectOptions(
        simulator::shrinkTaskSpecs(), {"input", "agent", "seed", "runs", "results", "min_rate", "any_kind", "by", "corpus"});
    list[0].flag = "shrink";
    list[0].doc = "INPUT: the graph of the shrink of this PPP file or set directory (absolute) into OUTPUT instead, "
                  "judged on --agent's nodes through the simulator (the other shrink flags: ppp shrink's)";
    return list;
  }();
  return specs;
}

/// The check's options `ppp launch-file` takes as flags of its own (--check CORPUS, --junit FILE); --agent, --seed
/// and --runs are the shrink's.
const std::vector<OptionSpec<simulator::CheckTask>>& checkFlagSpecs() {
  static const std::vector<OptionSpec<simulator::CheckTask>> specs = [] {
    std::vector<OptionSpec<simulator::CheckTask>> list = selectOptions(simulator::checkTaskSpecs(), {"corpus", "junit"});
    list[0].flag = "check";
    list[0].doc = "CORPUS: the graph of the check of --agent on every PPP of this directory or file instead, played through the simulator (--seed, --runs: for PPPs without recorded seeds; exit "
                  "status: ppp check's)";
    return list;
  }();
  return specs;
}

/// The check the flags ask for, if any: --check with --junit, and --agent, --seed and --runs of the shrink's flags.
/// @throws InvalidArgument naming the flag.
void applyCheckFlags(const LaunchFileFlags& flags, simulator::GraphOptions* graph) {
  applyOptionFlags(*flags.command, checkFlagSpecs(), flags.check_flags, &graph->check);
  if (graph->check.corpus.empty()) {
    if (flags.command->count(flagFor("junit")) > 0) {
      throw InvalidArgument(flagFor("junit"), "only a check takes it: give --check");
    }
    return;
  }
  if (flags.command->count("--shrink") > 0) throw InvalidArgument("--check", "a graph checks or shrinks, not both");
  for (const auto& spec : shrinkFlagSpecs()) {
    const std::string flag = flagName(spec);
    if (flags.command->count(flag) == 0) continue;
    if (spec.name == "agent") {
      graph->check.agent = graph->shrink.agent;
    } else if (spec.name == "seed") {
      graph->check.seed = graph->shrink.seed;
    } else if (spec.name == "runs") {
      graph->check.runs = graph->shrink.runs;
    } else {
      throw InvalidArgument(flag, "only a shrink takes it, not a check");
    }
  }
  graph->shrink = simulator::ShrinkTask{};
  graph->check.config = graph->config_path;
  graph->check.corpus = std::filesystem::absolute(graph->check.corpus).lexically_normal().string();
  if (!graph->check.junit.empty()) {
    graph->check.junit = std::filesystem::absolute(graph->check.junit).lexically_normal().string();
  }
  if (graph->check.agent.empty()) throw InvalidArgument(flagFor("agent"), "required: the agent to check");
}

/// The shrink the flags ask for, if any. @throws InvalidArgument naming the flag.
void applyShrinkFlags(const LaunchFileFlags& flags, simulator::GraphOptions* graph) {
  applyOptionFlags(*flags.command, shrinkFlagSpecs(), flags.shrink_flags, &graph->shrink);
  if (flags.command->count("--check") > 0) return applyCheckFlags(flags, graph);
  if (flags.command->count(flagFor("junit")) > 0) {
    throw InvalidArgument(flagFor("junit"), "only a check takes it: give --check");
  }
  if (graph->shrink.input.empty()) {
    for (const auto& spec : shrinkFlagSpecs()) {
      if (flags.command->count(flagName(spec)) > 0) {
        throw InvalidArgument(flagName(spec), "only a shrink takes it: give --shrink INPUT too");
      }
    }
    return;
  }
  graph->shrink.config = graph->config_path;
  graph->shrink.output = graph->output_dir;
  if (!std::filesystem::exists(graph->shrink.input)) {
    throw InvalidArgument("--shrink", "'" + graph->shrink.input + "' does not exist");
  }
}

void runLaunchFile(LaunchFileFlags flags) {
  namespace fs = std::filesystem;
  simulator::ExperimentConfig config = simulator::loadExperimentConfig(flags.config);
  simulator::assignPlanners(&config, flags.graph.planners);
  if (flags.graph.processes == agents::kProcessManager) flags.graph.simulator.batch_size = simulator::kManagerBatchSize;
  applyAndValidateFlags(*flags.command, simulator::simulatorOptionSpecs(), flags.simulator_flags,
                        &flags.graph.simulator);
  flags.graph.config_path = fs::absolute(flags.config).lexically_normal().string();
  flags.graph.output_dir = fs::absolute(flags.output).lexically_normal().string();
  applyShrinkFlags(flags, &flags.graph);
  const bool experiment = flags.graph.hunt.empty() && flags.graph.shrink.input.empty() && flags.graph.check.corpus.empty();
  if (experiment) {
    simulator::checkWork(simulator::estimateWork(config), flags.large);
    simulator::checkExperimentDirectory(config, flags.graph.output_dir);
    simulator::checkCorpora(config);
  }
  if (!flags.graph.hunt.empty()) generator::checkOutputDirectory(flags.graph.output_dir);
  ppp_msgs::LaunchGraph graph;
  try {
    graph = simulator::experimentGraph(config, flags.graph);
  } catch (const InvalidArgument& e) {
    throw namingTheFlag(*flags.command, shrinkFlagSpecs(), e);
  }
  std::cout << (flags.json ? ppp_msgs::launchJson(graph) : ppp_msgs::launchXml(graph));
}

}  // namespace

void addLaunchFileCommand(CLI::App& app) {
  auto flags = std::make_shared<LaunchFileFlags>();
  CLI::App* command = app.add_subcommand(
      "launch-file", "Write the roslaunch XML that runs an experiment through ROS (what launch/experiment.launch runs)");
  command->add_option("config", flags->config, "Experiment YAML (e.g. config/experiment.yaml)")->required();
  command->add_option("-o,--output", flags->output, "The experiment's output directory")->required();
  flags->command = command;
  static const simulator::SimulatorOptions defaults;
  addOptionFlags(command, simulator::simulatorOptionSpecs(), &defaults, &flags->simulator_flags);
  command->add_option("--planner", flags->graph.planners,
                      "NAME=PACKAGE/EXECUTABLE: start this planner for planner agent NAME, which then has 20 s to "
                      "connect (NAME=: start none; the user runs it in /NAME/robot within 300 s); overrides the "
                      "agent's planner_node");
  command->add_option("--hunt", flags->graph.hunt,
                      "SET: the graph of the hunt of this set of the config (fitness failure or regret) into OUTPUT "
                      "instead (panel agents only)");
  addOptionFlags(command, shrinkFlagSpecs(), &flags->graph.shrink, &flags->shrink_flags);
  addOptionFlags(command, checkFlagSpecs(), &flags->graph.check, &flags->check_flags);
  command->add_option("--env-loader", flags->graph.env_loader,
                      "Script remote machines run nodes through (the workspace's devel/env.sh, same path there)");
  command->add_option("--processes", flags->graph.processes,
                      "manager: the simulator, the generator nodes and the built-in agents (but those with process: "
                      "own or a host) run as nodelets in one nodelet manager; own: every node in a process of its own")
      ->capture_default_str();
  command->add_flag("--large", flags->large,
                    "Allow an experiment above the size limits (1e8 episodes or matings, 10 GB of results)");
  command->add_flag("--json", flags->json,
                    "Print the graph as JSON (machines with their agents, the required node, every node, the XML)");
  command->callback([flags] { runLaunchFile(*flags); });
}

}  // namespace cli
}  // namespace ppp
