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

}  // namespace cli
}  // namespace ppp
