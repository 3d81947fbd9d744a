#include <iostream>
#include <map>
#include <memory>
#include <string>

#include "commands.hpp"
#include "option_flags.hpp"
#include "stop_signals.hpp"
#include "ppp_core/csv.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_simulator/experiment_runner.hpp"
#include "ppp_simulator/hunt_corpus.hpp"
#include "progress.hpp"

namespace ppp {
namespace cli {

namespace {

/// The experiment options a flag may override over the config file's.
const std::vector<OptionSpec<simulator::ExperimentConfig>>& overridingSpecs() {
  static const auto specs = selectOptions(simulator::experimentOptionSpecs(), {"threads"});
  return specs;
}

struct ExperimentFlags {
  CLI::App* command = nullptr;
  std::string config;
  std::string output;
  std::map<std::string, std::string> overrides;
  bool large = false;
  bool quiet = false;
};

int runExperimentCommand(const ExperimentFlags& f) {
  simulator::ExperimentConfig config = simulator::loadExperimentConfig(f.config);
  applyAndValidateFlags(*f.command, overridingSpecs(), f.overrides, &config);
  const simulator::ExperimentWork work = simulator::estimateWork(config);
  simulator::checkWork(work, f.large);
  if (!f.quiet) std::cerr << "experiment: " << simulator::workSummary(work) << "\n";
  simulator::checkExperimentDirectory(config, f.output);
  const std::string config_text = readTextFile(f.config, 1u << 20);
  const StopCheck stop = stopOnSignals();
  Progress progress("episodes", f.quiet);
  const auto report = simulator::runExperiment(
      config, config_text, f.output, [&](long done, long total) { progress.update(done, total, f.output); },
      stop, [&](const std::string& line) {
        if (!f.quiet) std::cerr << line << "\n";
      });
  if (report.interrupted) {
    std::cerr << "ppp: interrupted after " << report.episodes_run
              << " new runs; every finished run is in results.csv. Rerun the same command to resume.\n";
    return 130;
  }
  std::cout << "experiment done: " << report.episodes_run << " runs simulated"
            << (report.episodes_resumed > 0 ? ", " + std::to_string(report.episodes_resumed) + " resumed" : "")
            << "\n  results:  " << f.output << "/results.csv\n  summary:  " << f.output
            << "/summary.csv\n  report:   " << f.output << "/report.html (and report.md)\n";
  for (const simulator::SetSpec& set : config.sets) {
    if (set.corpus.empty()) continue;
    std::cout << "  corpus:   " << set.corpus << " (" << set.name << "'s failures, shrunk; each in " << f.output
              << "/" << simulator::kCorpusLogFile << ")\n";
  }
  return 0;
}

}  // namespace

void addExperimentCommand(CLI::App& app) {
  auto flags = std::make_shared<ExperimentFlags>();
  CLI::App* command = app.add_subcommand(
      "experiment", "Evolve the PPP sets, run every agent on every PPP many times, write results and the report "
                    "(planner agents are skipped: they play only through ROS, launch/experiment.launch)");
  command->add_option("config", flags->config, "Experiment YAML (e.g. config/experiment.yaml)")->required();
  command->add_option("-o,--output", flags->output, "Output directory (rerun on it to resume)")->required();
  flags->command = command;
  addOptionFlags(command, overridingSpecs(), static_cast<const simulator::ExperimentConfig*>(nullptr),
                 &flags->overrides);
  command->add_flag("--large", flags->large,
                    "Run an experiment above the size limits (1e8 episodes or matings, 10 GB of results)");
  command->add_flag("--quiet", flags->quiet, "No progress output");
  command->callback([flags] {
    const int status = runExperimentCommand(*flags);
    if (status != 0) throw CLI::RuntimeError(status);
  });
}

}  // namespace cli
}  // namespace ppp
