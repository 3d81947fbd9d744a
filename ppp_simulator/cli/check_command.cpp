// `ppp check`: one agent on every PPP of a corpus on its recorded seeds, for CI: exit 0 when all pass, 1 when any
// fails, 2 on bad input; JUnit XML on request.
#include <iostream>
#include <map>
#include <memory>
#include <string>

#include "commands.hpp"
#include "core_commands.hpp"
#include "option_flags.hpp"
#include "ppp_agents/continuous/continuous_agent.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/option_yaml.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_simulator/corpus_check.hpp"
#include "ppp_simulator/experiment_config.hpp"
#include "stop_signals.hpp"

namespace ppp {
namespace cli {

namespace {

/// Bad input's exit status, whatever is wrong (CI tells a failing PPP, 1, from a broken check, 2).
constexpr int kBadInput = 2;

/// The check's options `ppp check` takes as flags (its corpus is its argument); without --config, --agent is a
/// built-in type played under the default episode rules.
const std::vector<OptionSpec<simulator::CheckTask>>& checkFlagSpecs() {
  static const std::vector<OptionSpec<simulator::CheckTask>> specs = [] {
    std::vector<OptionSpec<simulator::CheckTask>> list =
        selectOptions(simulator::checkTaskSpecs(), {"agent", "config", "seed", "runs", "junit"});
    list[0].doc = "the agent: a built-in type, or with --config the name of one of the config's agents";
    list[1].doc = "an experiment YAML: the agent and the episode rules come from it";
    return list;
  }();
  return specs;
}

struct CheckFlags {
  CLI::App* command = nullptr;
  std::string corpus;
  std::map<std::string, std::string> given;
};

/// The agent checked and its episode rules: the config's entry named `task.agent`, or the built-in type of that
/// name under the default rules.
std::pair<agents::AgentConfig, EpisodeOptions> checkedAgent(const simulator::CheckTask& task) {
  if (!task.config.empty()) {
    const simulator::ExperimentConfig config = simulator::loadExperimentConfig(task.config);
    try {
      return {simulator::configAgent(config, task.agent), config.episode};
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(flagFor("agent"), e.problem() + " (" + task.config + ")");
    }
  }
  agents::AgentConfig agent;
  agent.type = task.agent;
  agent.name = task.agent;
  try {
    agent.validate();
  } catch (const InvalidArgument&) {
    throw InvalidArgument(flagFor("agent"), "no built-in agent '" + task.agent + "' (valid: " +
                                                joinNames(agents::agentTypeNames()) + "); give " + flagFor("config") +
                                                " EXPERIMENT.yaml to check one of its agents");
  }
  return {agent, EpisodeOptions{}};
}

int runCheck(const CheckFlags& f) {
  if (!f.command->remaining().empty()) {
    throw InvalidArgument("check", "unexpected argument '" + f.command->remaining().front() + "'");
  }
  simulator::CheckTask task;
  applyOptionFlags(*f.command, checkFlagSpecs(), f.given, &task);
  try {
    checkOptionRanges(checkFlagSpecs(), task);
  } catch (const InvalidArgument& e) {
    throw namingTheFlag(*f.command, checkFlagSpecs(), e);
  }
  task.corpus = f.corpus;
  if (task.corpus.empty()) throw InvalidArgument("CORPUS", "required: a directory of PPP files, or one PPP file");
  if (task.agent.empty()) throw InvalidArgument(flagFor("agent"), "required: the agent to check");
  const auto [agent, episode] = checkedAgent(task);
  if (agents::isPlanner(agent)) {
    throw InvalidArgument(flagFor("agent"), "'" + agent.name + "' is a planner agent: planners play only through "
                                            "ROS; check it with launch/check.launch or scripts/ppp-check-ros");
  }
  agents::refuseContinuous(agent, episode);
  simulator::CheckJob job;
  job.task = task;
  job.episode = episode;
  job.play = [agent = agent, episode = episode](const Problem& problem, const std::vector<std::uint64_t>& seeds) {
    return simulator::playRuns(problem, agent, episode, seeds);
  };
  job.replay = [agent = agent, episode = episode](const simulator::CorpusCase& c, std::uint64_t seed) {
    return agents::replayCommand(c.file, agent, episode, seed);
  };
  return simulator::runCheck(job, stopOnSignals(), std::cout);
}

}  // namespace

void addCheckCommand(CLI::App& app) {
  auto flags = std::make_shared<CheckFlags>();
  CLI::App* command = app.add_subcommand(
      "check", "Play an agent on every PPP of a corpus on its recorded seeds: exit 0 when all pass, 1 when any fails, "
               "2 on bad input (docs/how-to/regression-corpus.md)");
  flags->command = command;
  command->allow_extras();
  setUsageErrorStatus(command, kBadInput);
  command->add_option("corpus", flags->corpus,
                      "A directory of PPP files (.ppp, map_server .yaml, MovingAI .map; a set's set.csv order, else "
                      "file-name order), or one PPP file");
  static const simulator::CheckTask defaults;
  addOptionFlags(command, checkFlagSpecs(), &defaults, &flags->given);
  command->callback([flags] {
    int status = 0;
    try {
      status = runCheck(*flags);
    } catch (const std::exception& e) {  // ppp::Error, or a filesystem error: bad input either way
      std::cerr << "ppp: error: " << e.what() << "\n";
      throw CLI::RuntimeError(kBadInput);
    }
    if (status != 0) throw CLI::RuntimeError(status);
  });
}

}  // namespace cli
}  // namespace ppp
