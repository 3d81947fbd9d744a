#pragma once

#include <CLI/CLI.hpp>

namespace ppp {
namespace cli {

/// Adds `ppp generate`: evolve a PPP set and write it with its taxonomy.
void addGenerateCommand(CLI::App& app);
/// Adds `ppp tree`: rebuild a set's taxonomy over a character set.
void addTreeCommand(CLI::App& app);
/// Adds `ppp select`: pick k diverse PPPs of a set.
void addSelectCommand(CLI::App& app);

/// Adds `ppp export`: write a set's PPPs in another format (MovingAI .map with a .scen, map_server, ...).
void addExportCommand(CLI::App& app);
/// Adds every generator subcommand.
inline void addGeneratorCommands(CLI::App& app) {
  addGenerateCommand(app);
  addTreeCommand(app);
  addSelectCommand(app);
  addExportCommand(app);
}

}  // namespace cli
}  // namespace ppp
