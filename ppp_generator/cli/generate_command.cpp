#include <iostream>
#include <map>
#include <optional>
#include <memory>
#include <string>
#include <vector>

#include "generator_commands.hpp"
#include "cli_options.hpp"
#include "option_flags.hpp"
#include "stop_signals.hpp"
#include "ppp_core/csv.hpp"
#include "ppp_core/episode_options.hpp"
#include "ppp_generator/failure_fitness.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_generator/set_evolution.hpp"
#include "progress.hpp"

namespace ppp {
namespace cli {

namespace {

struct GenerateFlags {
  std::string config = PPP_DEFAULT_CONFIG_DIR "/generator.yaml";
  std::map<std::string, std::string> options;  ///< The generator options' flags given, by flag name.
  std::map<std::string, std::string> episode;  ///< The episode options' flags given (panel fitnesses), by flag name.
  std::string size;                            ///< --size WIDTHxHEIGHT, as `ppp random` takes it.
  int threads = 0;
  std::string output;
  bool quiet = false;
  bool print_options = false;
};

/// The options of --config with the option flags applied. @throws IoError, ParseError, InvalidArgument.
generator::GeneratorOptions resolveOptions(const CLI::App& command, const GenerateFlags& f) {
  generator::GeneratorOptions o = generator::loadGeneratorOptions(f.config);
  if (command.count("--size") > 0) {
    for (const auto& side : selectOptions(generator::generatorOptionSpecs(), {"width", "height"})) {
      if (command.count(flagName(side)) > 0) {
        throw InvalidArgument("--size", "give either --size or " + flagName(side) + ", not both");
      }
    }
    const Size size = parseSize(f.size, "--size");
    o.width = size.width;
    o.height = size.height;
  }
  applyAndValidateFlags(command, generator::generatorOptionSpecs(), f.options, &o);
  return o;
}

/// Whether any flag of the episode options or --threads was given (they serve the panel fitnesses only).
bool episodeFlagsGiven(const CLI::App& command) {
  for (const OptionSpec<EpisodeOptions>& spec : generator::huntEpisodeOptionSpecs()) {
    if (command.count(flagName(spec)) > 0) return true;
  }
  return command.count("--threads") > 0;
}

void runGenerate(const CLI::App& command, const GenerateFlags& flags) {
  if (flags.print_options) {
    std::cout << "# Default options of the PPP generator (ppp generate, generator_node, the sets of an experiment), as\n"
                 "# `ppp generate --print-options` prints them: flags (--max-obstacles) and node parameters (~max_obstacles,\n"
                 "# ~weights/goal) of the same names override them. Unknown keys are errors.\n"
              << generator::generatorOptionsYaml(generator::GeneratorOptions{}, true);
    return;
  }
  if (flags.output.empty()) throw InvalidArgument("--output", "required: the set's directory");
  const generator::GeneratorOptions options = resolveOptions(command, flags);
  if (!generator::isPanelFitness(options.fitness) && episodeFlagsGiven(command)) {
    throw InvalidArgument(flagName(optionNamed(generator::generatorOptionSpecs(), "fitness")),
                          "the episode flags (--budget, --sensor-range, ...) and --threads are for the panel fitnesses "
                          "(failure, regret), which play episodes; this run's fitness is " + options.fitness);
  }
  EpisodeOptions episode;
  applyAndValidateFlags(command, generator::huntEpisodeOptionSpecs(), flags.episode, &episode);
  const generator::Fitness fitness = generator::fitnessFor(options, episode, flags.threads);
  Progress progress("matings", flags.quiet);
  const generator::EvolvedSet evolved = generator::evolveSetDirectory(
      flags.output, options, fitness,
      [&](long done, long total, double best) {
        progress.update(done, total, "best " + options.fitness + " " + formatNumber(best));
      },
      stopOnSignals());
  std::cout << "wrote " << evolved.set.problems.size() << " PPPs, set.csv, generator.yaml and tree.{nwk,json,html}"
            << (options.archive == generator::kMapElitesArchive ? ", archive.{csv,svg}" : "") << " to "
            << flags.output << " (" << evolved.summary << ")\n";
}

}  // namespace

void addGenerateCommand(CLI::App& app) {
  auto flags = std::make_shared<GenerateFlags>();
  CLI::App* command = app.add_subcommand(
      "generate", "Evolve a set of PPPs with the genetic algorithm; write the .ppp files, set.csv and the taxonomy");
  command->add_option("--config", flags->config,
                      "Generator YAML whose values the flags override (default: the workspace's "
                      "config/generator.yaml)");
  static const generator::GeneratorOptions defaults;
  addOptionFlags(command, generator::generatorOptionSpecs(), &defaults, &flags->options);
  command->add_option("--size", flags->size, "grid size, for --width and --height together")->type_name("WIDTHxHEIGHT");
  static const EpisodeOptions episode_defaults;
  addOptionFlags(command, generator::huntEpisodeOptionSpecs(), &episode_defaults, &flags->episode);
  command->add_option("--threads", flags->threads, "failure, regret: worker threads (default 0: every core)");
  command->add_option("-o,--output", flags->output, "Output directory (required)");
  command->add_flag("--print-options", flags->print_options,
                    "Print every generator option with its default, range and doc as YAML (config/generator.yaml)");
  command->add_flag("--quiet", flags->quiet, "No progress output");
  command->callback([command, flags] { runGenerate(*command, *flags); });
}

}  // namespace cli
}  // namespace ppp
