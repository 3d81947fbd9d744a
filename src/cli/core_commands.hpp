#pragma once

#include <CLI/CLI.hpp>

namespace ppp {
namespace cli {

// The core's subcommands (ROS-free): in the workspace's `ppp` and in the core build's own `ppp-core`.

/// Adds `ppp random`: draw a solvable random PPP.
void addRandomCommand(CLI::App& app);
/// Adds `ppp evaluate`: every measure of one or more PPPs, as text, JSON or CSV.
void addEvaluateCommand(CLI::App& app);
/// Adds `ppp convert`: between .ppp, map_server .yaml, MovingAI .map, .png and OctoMap .bt.
void addConvertCommand(CLI::App& app);

/// Adds every core subcommand.
inline void addCoreCommands(CLI::App& app) {
  addRandomCommand(app);
  addEvaluateCommand(app);
  addConvertCommand(app);
}

/// Makes `status` the exit status of a command line that `command` cannot parse (a missing flag value, say), in
/// place of CLI11's own, for a command whose statuses a CI system reads.
void setUsageErrorStatus(const CLI::App* command, int status);

/// Parses `argv` into `app` and runs the chosen subcommand; returns the exit status (errors printed as
/// "<program>: error: ..." on stderr).
int runCommandLine(CLI::App& app, int argc, char** argv, const char* program);

}  // namespace cli
}  // namespace ppp
