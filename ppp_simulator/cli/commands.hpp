#pragma once

#include <CLI/CLI.hpp>

namespace ppp {
namespace cli {

/// Adds `ppp random`: draw a solvable random PPP.
void addRandomCommand(CLI::App& app);
/// Adds `ppp evaluate`: every measure of one or more PPPs, as text, JSON or CSV.
void addEvaluateCommand(CLI::App& app);
/// Adds `ppp convert`: between .ppp, map_server .yaml, .png and OctoMap .bt.
void addConvertCommand(CLI::App& app);
/// Adds `ppp generate`: evolve a PPP set and write it with its taxonomy.
void addGenerateCommand(CLI::App& app);
/// Adds `ppp tree`: rebuild a set's taxonomy over a character set.
void addTreeCommand(CLI::App& app);
/// Adds `ppp select`: pick k diverse PPPs of a set.
void addSelectCommand(CLI::App& app);

}  // namespace cli
}  // namespace ppp
