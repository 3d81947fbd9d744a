#include <iostream>
#include <sstream>
#include <string>

#include "commands.hpp"
#include "planner_node_options.hpp"
#include "ppp_agents/planner_bridge_options.hpp"
#include "ppp_core/option_docs.hpp"
#include "ppp_generator/generator_node_options.hpp"
#include "ppp_generator/generator_options.hpp"
#include "ppp_simulator/experiment_config.hpp"
#include "ppp_simulator/corpus_check.hpp"
#include "ppp_simulator/shrink_job.hpp"
#include "ppp_simulator/simulator_options.hpp"

namespace ppp {
namespace cli {

namespace {

/// An option as a YAML key.
template <typename Options>
std::string key(const OptionSpec<Options>& spec) {
  return spec.name;
}

/// An option as a `~` parameter ("weights.goal" is ~weights/goal).
template <typename Options>
std::string parameter(const OptionSpec<Options>& spec) {
  std::string name = "~" + spec.name;
  for (char& c : name) c = c == '.' ? '/' : c;
  return name;
}

/// The options' spellings by `spell`, as prose: "`a`, `b` and `c`".
template <typename Options, typename Spell>
std::string spelledList(const std::vector<OptionSpec<Options>>& specs, Spell spell) {
  std::string list;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    if (i > 0) list += i + 1 == specs.size() ? " and " : ", ";
    list += "`" + spell(specs[i]) + "`";
  }
  return list;
}

/// The options reference (docs/reference/options.md): every declared options struct, each source's spelling.
std::string optionsReference() {
  std::ostringstream out;
  out << "# Options reference\n\n"
      << "Generated from the option declarations by `scripts/ppp options` (a test keeps this file equal to its\n"
      << "output). Each option is declared once, with its type, range, default and meaning; the YAML files, ROS\n"
      << "parameters and command-line flags below all read it from that declaration and accept and refuse the\n"
      << "same values. A flag is `--` plus the name with `_` and `.` as `-` (`--weights-goal`); a ROS parameter is\n"
      << "`~` plus the name with `.` as `/` (`~weights/goal`). An option that changes results is part of an\n"
      << "experiment's fingerprint (its `experiment.yaml`): a rerun on the same directory resumes only when\n"
      << "every such option is unchanged, and otherwise names the first one that differs.\n\n"
      << "## Experiment\n\n"
      << "Top-level keys of an experiment YAML (`config/experiment.yaml`) besides `sets`, `agents` and `reference`\n"
      << "([write an experiment file](../how-to/write-an-experiment-file.md)); `ppp experiment --threads` overrides\n"
      << "`threads`.\n\n"
      << optionsMarkdownTable(simulator::experimentOptionSpecs(), simulator::ExperimentConfig{}, &key)
      << "\n## Agents\n\n"
      << "Keys of each entry of an `agents` list (`config/agents.yaml`).\n"
      << "`agent_node` reads " << spelledList(agents::agentNodeOptionSpecs(), &parameter<agents::AgentConfig>)
      << "; `planner_bridge_node` reads `~name`, `~memory` and `~sensor_noise`; `ppp simulate`, `ppp replay` and "
      << "`ppp scenarios` take " << spelledList(agents::agentPlayOptionSpecs(), &flagName<agents::AgentConfig>)
      << " (`--agent` is the type), with the episode's options (`--budget`, `--sensor-range`, ...).\n\n"
      << optionsMarkdownTable(agents::agentOptionSpecs(), agents::AgentConfig{}, &key)
      << "\n## Generator\n\n"
      << "Keys of `config/generator.yaml` and of a set's `generator` mapping, `generator_node` `~` parameters and\n"
      << "`ppp generate` flags (`--size WIDTHxHEIGHT` sets `width` and `height` together, as for `ppp random`;\n"
      << "the panel fitnesses, failure and regret, also take the episode options' flags: `--budget`, `--budget-factor`,\n"
      << "`--sensor-range`, `--connectivity`, `--soft-failure-ratio`, ...).\n\n"
      << optionsMarkdownTable(generator::generatorOptionSpecs(), generator::GeneratorOptions{}, &key)
      << "\n## Generator node\n\n"
      << "`generator_node` `~` parameters besides the generator options above (which it reads as `~options`, YAML\n"
      << "text, and as single parameters of their names).\n\n"
      << optionsMarkdownTable(generator::generatorNodeOptionSpecs(), generator::GeneratorNodeOptions{}, &parameter)
      << "\n## Simulator node\n\n"
      << "`simulator_node` `~` parameters, each also a `ppp launch-file` flag (`launch/experiment.launch` and\n"
      << "`hunt.launch` pass the flags of their `args` on).\n\n"
      << optionsMarkdownTable(simulator::simulatorOptionSpecs(), simulator::SimulatorOptions{}, &parameter)
      << "\nWhat the node runs, set by the graph `ppp launch-file` writes (`~mode`, `~config`, `~output_dir`,\n"
      << "`~generator_nodes`):\n\n"
      << optionsMarkdownTable(simulator::simulatorTaskSpecs(), simulator::SimulatorTask{}, &parameter)
      << "\n## Shrink node\n\n"
      << "`shrink_node` `~` parameters ([shrink a failure](../how-to/shrink-a-failure.md)): `ppp shrink` for any\n"
      << "agent of an experiment, judged through the simulator serving hunts. `launch/shrink.launch` sets them\n"
      << "from `ppp launch-file --shrink INPUT --agent NAME` and that command's flags of the same names;\n"
      << "`ppp shrink` takes `--results`, `--min-rate`, `--by` and `--corpus`.\n\n"
      << optionsMarkdownTable(simulator::shrinkTaskSpecs(), simulator::ShrinkTask{}, &parameter)
      << "\n## Check node\n\n"
      << "`check_node` `~` parameters ([keep failures as regression tests](../how-to/regression-corpus.md)):\n"
      << "`ppp check` for any agent of an experiment, its runs played through the simulator serving hunts.\n"
      << "`launch/check.launch` and `scripts/ppp-check-ros` set them from `ppp launch-file --check CORPUS\n"
      << "--agent NAME` and that command's `--seed`, `--runs` and `--junit`; `ppp check` takes the same as flags.\n\n"
      << optionsMarkdownTable(simulator::checkTaskSpecs(), simulator::CheckTask{}, &parameter)
      << "\n## Planner bridge node\n\n"
      << "`planner_bridge_node` `~` parameters besides its agent's `~name`, `~memory` and `~sensor_noise`\n"
      << "([the planner interface](planner-interface.md)).\n\n"
      << optionsMarkdownTable(agents::bridgeOptionSpecs(), agents::BridgeOptions{}, &parameter)
      << "\n## Example planner nodes\n\n"
      << "`~` parameters of `optimistic_planner_node`, `ompl_planner_node` and `mrpt_planner_node` (the frames\n"
      << "they plan in):\n\n"
      << optionsMarkdownTable(planners::plannerFrameSpecs(), planners::PlannerFrames{}, &parameter)
      << "\nand the robot's body as they believe it:\n\n"
      << optionsMarkdownTable(planners::plannerBodySpecs(), planners::PlannerBody{}, &parameter)
      << "\nand of `ompl_planner_node` alone:\n\n"
      << optionsMarkdownTable(planners::omplNodeOptionSpecs(), planners::OmplNodeParameters{}, &parameter)
      << "\nand of `mrpt_planner_node` alone (its `~inflation` is MRPT's own robot radius):\n\n"
      << optionsMarkdownTable(planners::mrptNodeOptionSpecs(), planners::MrptNodeParameters{}, &parameter)
      << "\n`mrpt_reactive_node` (a local planner answering on `cmd_vel`) reads the frames above and:\n\n"
      << optionsMarkdownTable(planners::reactiveNodeOptionSpecs(), planners::ReactiveNodeParameters{}, &parameter)
      << "\nIn continuous motion it, `mrpt_tpspace_node` and `echo_planner_node` (which answers every period at\n"
      << "once, standing still) read the control period the graph sets, to tell a period that continues an episode\n"
      << "from one that begins the next ([the planner interface](planner-interface.md)):\n\n"
      << optionsMarkdownTable(planners::plannerPeriodSpecs(), planners::PlannerPeriod{}, &parameter)
      << "\n`dwa_planner_node` (a dynamic-window local planner answering on `cmd_vel`) reads the frames above and\n"
      << "the robot's description, which the experiment's graph sets in continuous motion from the motion options\n"
      << "(on the grid the window samples standing and the four moves), and its window's weights:\n\n"
      << optionsMarkdownTable(planners::dwaNodeOptionSpecs(), planners::DwaNodeParameters{}, &parameter)
      << "\n`mrpt_tpspace_node` (MRPT's TP-space navigator, a local planner answering on `cmd_vel` in continuous\n"
      << "motion only) reads the frames above, its configuration and the robot's description, which the experiment's\n"
      << "graph sets from the motion options:\n\n"
      << optionsMarkdownTable(planners::tpSpaceNodeOptionSpecs(), planners::TpSpaceNodeParameters{}, &parameter)
      << "\n`zoo_planner_node` (the optimistic planner with one planted fault, for measuring hunts:\n"
      << "`scripts/bench-hunt.sh`) reads the frames above and:\n\n"
      << optionsMarkdownTable(planners::zooNodeOptionSpecs(), planners::ZooNodeParameters{}, &parameter);
  return out.str();
}

}  // namespace

void addOptionsCommand(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "options", "Print the options reference: every declared option of experiments, agents, the generator and the "
                 "simulator node (docs/reference/options.md)");
  command->callback([] { std::cout << optionsReference(); });
}

}  // namespace cli
}  // namespace ppp
