// `ppp shrink`: the smallest PPP on which an agent still fails the same way, for one PPP or a whole set.
#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "agent_flags.hpp"
#include "commands.hpp"
#include "option_flags.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/ppp_file.hpp"
#include "ppp_core/problem_io.hpp"
#include "ppp_core/progress_meter.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_simulator/failure_shrink.hpp"
#include "ppp_simulator/results_file.hpp"
#include "stop_signals.hpp"

namespace ppp {
namespace cli {

namespace {

namespace fs = std::filesystem;

struct ShrinkFlags {
  CLI::App* command = nullptr;
  AgentFlags agent;
  std::string input;
  std::string output;
  std::string agents_file;
  std::uint64_t seed = 1;
  int runs = 0;
  bool any_kind = false;
  double min_rate = 0;
  std::string units;
  std::string results;
};

/// The failing runs' seeds of results.csv, per (set, PPP), for the agent shrunk for.
using FailingSeeds = std::map<std::pair<std::string, std::string>, std::vector<std::uint64_t>>;

/// The seeds of `agent`'s failed runs in the results file `path`, in run order, at most `most` per PPP.
FailingSeeds failingSeeds(const std::string& path, const std::string& agent, int most) {
  std::vector<agents::EpisodeResult> failed = simulator::readResultsFile(path);
  failed.erase(std::remove_if(failed.begin(), failed.end(),
                              [&](const agents::EpisodeResult& r) { return r.agent != agent || r.passed; }),
               failed.end());
  std::sort(failed.begin(), failed.end(), [](const auto& a, const auto& b) { return a.run < b.run; });
  FailingSeeds seeds;
  for (const agents::EpisodeResult& r : failed) {
    std::vector<std::uint64_t>& list = seeds[{r.set, r.problem}];
    if (static_cast<int>(list.size()) < most) list.push_back(r.seed);
  }
  return seeds;
}

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
  if (f.command->count("--runs") > 0 && (f.runs < 1 || f.runs > 100000)) {
    throw InvalidArgument("--runs", "expected a number of runs in [1, 100000], got " + std::to_string(f.runs));
  }
  if (f.command->count("--runs") == 0) return {f.seed};
  std::vector<std::uint64_t> seeds;
  for (int run = 0; run < f.runs; ++run) seeds.push_back(deriveSeed(f.seed, {static_cast<std::uint64_t>(run)}));
  return seeds;
}

/// What a file is shrunk over: --by, else descriptors for .ppp files and cells for imported maps.
ShrinkUnits unitsFor(const ShrinkFlags& f, const std::string& path) {
  if (f.units == "descriptors") return ShrinkUnits::Descriptors;
  if (f.units == "cells") return ShrinkUnits::Cells;
  if (!f.units.empty()) throw InvalidArgument("--by", "expected descriptors or cells, got '" + f.units + "'");
  return fileExtension(path) == ".ppp" ? ShrinkUnits::Descriptors : ShrinkUnits::Cells;
}

std::string summary(const simulator::ShrunkFailure& s, double seconds) {
  const std::string kind = s.kept.kind.empty() ? "any failure" : s.kept.kind;
  return std::to_string(s.descriptors_before) + " -> " + std::to_string(s.descriptors_after) + " descriptors, " +
         std::to_string(s.cells_before) + " -> " + std::to_string(s.cells_after) + " obstacle cells, still " +
         kind + " in " + *findMetadata(s.problem.metadata, "shrink_failed") + " runs (" +
         std::to_string(s.evaluations) + " candidates, " + formatFixed(seconds * 1000, 1) + " ms)";
}

/// The name of the directory `path` is (a set's name, as results.csv has it).
std::string directoryName(const fs::path& path) {
  return path.filename().empty() ? path.parent_path().filename().string() : path.filename().string();
}

int shrinkOne(const ShrinkFlags& f, simulator::FailureJudging judging, const FailingSeeds* failing,
              const StopCheck& stop) {
  if (failing != nullptr) {
    const std::string set = directoryName(fs::absolute(f.input).parent_path());
    const std::string id = fs::path(f.input).stem().string();
    const auto found = failing->find({set, id});
    if (found == failing->end()) {
      throw InvalidArgument("--results", "no failed run of " + judging.agent.name + " on " + set + "/" + id + " in " +
                                             f.results);
    }
    judging.seeds = found->second;
  }
  const Problem problem = readProblemFile(f.input);
  const double start = steadySeconds();
  const simulator::ShrunkFailure shrunk =
      simulator::shrinkFailure(problem, fs::path(f.input).filename().string(), judging, unitsFor(f, f.input), stop);
  writePppFile(shrunk.problem, f.output);
  std::cout << judging.agent.name << " on " << f.input << ": " << summary(shrunk, steadySeconds() - start) << "; written to "
            << f.output << "\n";
  return 0;
}

int shrinkSet(const ShrinkFlags& f, simulator::FailureJudging judging, const FailingSeeds* failing,
              const StopCheck& stop) {
  const std::size_t runs = judging.seeds.size();
  if (fs::exists(f.output) && !(fs::is_directory(f.output) && fs::is_empty(f.output))) {
    throw InvalidArgument("--output", "'" + f.output + "' exists and is not an empty directory");
  }
  const ProblemSet set = generator::readProblemSetDirectory(f.input);
  std::vector<std::pair<std::string, Problem>> shrunk;  // written only once every PPP is done
  for (std::size_t i = 0; i < set.problems.size(); ++i) {
    const std::string name = set.ids[i] + ".ppp";
    const double start = steadySeconds();
    if (failing != nullptr) {
      const auto found = failing->find({directoryName(f.input), set.ids[i]});
      if (found == failing->end()) {
        std::cout << name << ": no failed run of " << judging.agent.name << " in " << f.results << ", kept out\n";
        continue;
      }
      judging.seeds = found->second;
    }
    try {
      const simulator::ShrunkFailure s =
          simulator::shrinkFailure(set.problems[i], name, judging, unitsFor(f, name), stop);
      std::cout << name << ": " << summary(s, steadySeconds() - start) << "\n";
      shrunk.emplace_back(name, s.problem);
    } catch (const InvalidArgument& e) {
      if (e.name() != "problem") throw;
      std::cout << name << ": " << e.problem() << ", kept out\n";
    }
  }
  if (shrunk.empty()) {
    std::cerr << "ppp: " << judging.agent.name << " fails none of the " << set.problems.size() << " PPPs of " << f.input
              << (failing != nullptr ? " with a failed run in " + f.results : " in the " + std::to_string(runs) + " runs judged")
              << ": nothing to shrink, nothing written\n";
    return 1;
  }
  fs::create_directories(f.output);
  for (const auto& [name, problem] : shrunk) writePppFile(problem, (fs::path(f.output) / name).string());
  std::cout << shrunk.size() << " of " << set.problems.size() << " PPPs shrunk into " << f.output << "\n";
  return 0;
}

int runShrink(const ShrinkFlags& f) {
  simulator::FailureJudging judging;
  judging.agent = agentToShrinkFor(f);
  judging.episode = f.agent.episode();
  judging.seeds = judgedSeeds(f);
  judging.any_kind = f.any_kind;
  judging.min_rate = f.min_rate;
  if (f.command->count("--min-rate") > 0 && !(f.min_rate > 0 && f.min_rate <= 1)) {
    throw InvalidArgument("--min-rate", "expected a share of the runs in (0, 1], got " + formatShortest(f.min_rate));
  }
  unitsFor(f, f.input);  // a bad --by is refused before any run
  if (!fs::exists(f.input)) throw InvalidArgument("input", "'" + f.input + "' does not exist");
  std::optional<FailingSeeds> failing;
  if (!f.results.empty()) failing = failingSeeds(f.results, judging.agent.name, f.command->count("--runs") > 0 ? f.runs : 3);
  const StopCheck stop = stopOnSignals();
  try {
    const FailingSeeds* seeds = failing ? &*failing : nullptr;
    return fs::is_directory(f.input) ? shrinkSet(f, judging, seeds, stop) : shrinkOne(f, judging, seeds, stop);
  } catch (const Interrupted&) {
    std::cerr << "ppp: interrupted; nothing written\n";
    return 130;
  } catch (const InvalidArgument& e) {
    if (e.name() != "problem") throw;
    std::cerr << "ppp: " << e.problem() << "; nothing written\n";
    return 1;
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
  command->add_option("-o,--output", flags->output, "The shrunk .ppp file (a new directory for a set)")->required();
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
  command->add_option("--results", flags->results,
                      "An experiment's results.csv: judge each PPP on the seeds of the agent's failed runs there "
                      "(the set is the PPP's directory name)");
  command->add_option("--min-rate", flags->min_rate,
                      "Keep only candidates on which at least this share of the runs fail so, in (0, 1] (default: "
                      "the original's share)");
  command->add_flag("--any-kind", flags->any_kind,
                    "Keep any failure, not only the diagnosis most of the failing runs had");
  command->add_option("--by", flags->units,
                      "descriptors (the default for .ppp files) or cells (the default for imported maps)");
  command->callback([flags] {
    const int status = runShrink(*flags);
    if (status != 0) throw CLI::RuntimeError(status);
  });
}

}  // namespace cli
}  // namespace ppp
