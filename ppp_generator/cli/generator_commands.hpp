#pragma once

#include <functional>
#include <optional>

#include <CLI/CLI.hpp>

#include "ppp_core/episode_options.hpp"
#include "ppp_generator/fitness.hpp"
#include "ppp_generator/generator_options.hpp"

namespace ppp {
namespace cli {

/// Makes the `failure` fitness of `ppp generate` (its episodes are the simulator's): the options, the episode
/// rules of the flags (validated) and --threads. @throws InvalidArgument, IoError, ParseError.
using FailureFitnessMaker = std::function<generator::Fitness(const generator::GeneratorOptions& options,
                                                             const EpisodeOptions& episode, int threads)>;

/// Adds `ppp generate`: evolve a PPP set and write it with its taxonomy.
void addGenerateCommand(CLI::App& app, FailureFitnessMaker make_failure_fitness);
/// Adds `ppp tree`: rebuild a set's taxonomy over a character set.
void addTreeCommand(CLI::App& app);
/// Adds `ppp select`: pick k diverse PPPs of a set.
void addSelectCommand(CLI::App& app);

/// Adds `ppp export`: write a set's PPPs in another format (MovingAI .map with a .scen, map_server, ...).
void addExportCommand(CLI::App& app);
/// Adds every generator subcommand.
inline void addGeneratorCommands(CLI::App& app, FailureFitnessMaker make_failure_fitness) {
  addGenerateCommand(app, std::move(make_failure_fitness));
  addTreeCommand(app);
  addSelectCommand(app);
  addExportCommand(app);
}

}  // namespace cli
}  // namespace ppp
