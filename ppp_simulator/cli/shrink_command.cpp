// `ppp shrink`: the smallest PPP on which an agent still fails the same way, for one PPP or a whole set.
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "agent_flags.hpp"
#include "commands.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/text_format.hpp"
#include "option_flags.hpp"
#include "ppp_simulator/shrink_job.hpp"
#include "stop_signals.hpp"

namespace ppp {
namespace cli {

namespace {

/// The shrink options `ppp shrink` takes from their declaration (its input, agent, seeds and runs are its own).
const std::vector<OptionSpec<simulator::ShrinkTask>>& shrinkFlagSpecs() {
  static const std::vector<OptionSpec<simulator::ShrinkTask>> specs =
      selectOptions(simulator::shrinkTaskSpecs(), {"results", "min_rate", "by", "corpus"});
  return specs;
}

struct ShrinkFlags {
  CLI::App* command = nullptr;
  AgentFlags agent;
  std::string input;
  std::string output;
  std::string agents_file;
  std::uint64_t seed = 1;
  int runs = 0;
  bool any_kind = false;
  std::map<std::string, std::string> given;  // the declared flags, by name
};

/// The agent to shrink for: the flags' built-in type, or the entry named by --agent in --agents-file.
agents::AgentConfig agentToShrinkFor(const ShrinkFlags& f) {
  if (f.agents_file.empty()) return f.agent.agent();
  const std::string name = f.command->get_option("--agent")->as<std::string>();
  const std::vector<agents::AgentConfig> configs = agents::loadAgentConfigs(f.agents_file);
  std::vector<std::string> names;
  for (const agents::AgentConfig& c : configs) {
    if (c.name != name) {
      names.push_back(c.name);
      continue;
    }
    if (agents::isPlanner(c)) {
      throw InvalidArgument("--agent", "'" + name + "' is a planner agent: planners play only through ROS; shrink "
                                       "its failures with launch/shrink.launch");
    }
    return c;
  }
  throw InvalidArgument("--agent", "no agent '" + name + "' in " + f.agents_file + "; it has: " + joinNames(names));
}

/// The run seeds judged: --seed alone, or --runs seeds derived from it as `ppp simulate` derives them (with
/// --results, each PPP's failing runs' seeds replace them).
std::vector<std::uint64_t> judgedSeeds(const ShrinkFlags& f) {
  if (f.command->count("--runs") == 0) return {f.seed};
  if (f.runs < 1 || f.runs > simulator::kMaxJudgedRuns) {
    throw InvalidArgument("--runs", "expected a number of runs in [1, " + std::to_string(simulator::kMaxJudgedRuns) +
                                        "], got " + std::to_string(f.runs));
  }
  return simulator::derivedRunSeeds(f.seed, f.runs);
}

int runShrink(const ShrinkFlags& f) {
  simulator::ShrinkTask task;
  applyOptionFlags(*f.command, shrinkFlagSpecs(), f.given, &task);
  simulator::ShrinkJob job;
  job.input = f.input;
  job.output = f.output;
  job.corpus = task.corpus;
  job.judging.agent = agentToShrinkFor(f);
  job.judging.episode = f.agent.episode();
  job.judging.seeds = judgedSeeds(f);
  job.judging.any_kind = f.any_kind;
  job.judging.min_rate = task.min_rate;
  job.results = task.results;
  if (f.command->count("--runs") > 0) job.results_runs = f.runs;
  job.units = task.by;
  job.replay = [agent = job.judging.agent, episode = job.judging.episode](const std::string& file, std::uint64_t seed) {
    return agents::replayCommand(file, agent, episode, seed);
  };
  try {
    return simulator::runShrinkJob(job, stopOnSignals(), std::cout, std::cerr);
  } catch (const InvalidArgument& e) {
    throw namingTheFlag(*f.command, shrinkFlagSpecs(), e);
  }
}

}  // namespace

void addShrinkCommand(CLI::App& app) {
  auto flags = std::make_shared<ShrinkFlags>();
  CLI::App* command = app.add_subcommand(
      "shrink", "The smallest PPP on which an agent still fails the same way: on the same run seeds, at least as "
                "often, with the same diagnosis (docs/how-to/shrink-a-failure.md)");
  flags->command = command;
  command->add_option("input", flags->input,
                      "A .ppp, map_server .yaml or MovingAI .map file, or a set directory (each failing PPP shrunk)")
      ->required();
  flags->agent.add(command);
  command->add_option("-o,--output", flags->output,
                      "The shrunk .ppp file (a new directory for a set); required unless --corpus is given");
  command->add_option("--agents-file", flags->agents_file,
                      "Agents YAML (an experiment's agents list): --agent names one of its entries, handicaps "
                      "included");
  command->add_option("--seed", flags->seed,
                      "The failing run's seed (results.csv's seed column); with --runs, the seed their seeds derive "
                      "from, as in ppp simulate")
      ->capture_default_str();
  command->add_option("--runs", flags->runs,
                      "Judge this many runs, seeded as ppp simulate seeds them (with --results: at most this many of "
                      "each PPP's failed runs, default 3)");
  static const simulator::ShrinkTask defaults;
  addOptionFlags(command, shrinkFlagSpecs(), &defaults, &flags->given);
  command->add_flag("--any-kind", flags->any_kind,
                    "Keep any failure, not only the diagnosis most of the failing runs had");
  command->callback([flags] {
    const int status = runShrink(*flags);
    if (status != 0) throw CLI::RuntimeError(status);
  });
}

}  // namespace cli
}  // namespace ppp
