#pragma once

#include <CLI/CLI.hpp>

namespace ppp {
namespace cli {

// The simulator's subcommands of `ppp` (the core's and the generator's live beside their libraries).

/// Adds `ppp simulate`: one agent, many runs, one PPP.
void addSimulateCommand(CLI::App& app);
/// Adds `ppp replay`: one episode drawn as a picture.
void addReplayCommand(CLI::App& app);
/// Adds `ppp shrink`: the smallest PPP on which an agent still fails the same way.
void addShrinkCommand(CLI::App& app);
/// Adds `ppp check`: an agent on every PPP of a corpus, for CI.
void addCheckCommand(CLI::App& app);
/// Adds `ppp scenarios`: one agent on every scenario of a MovingAI .scen file.
void addScenariosCommand(CLI::App& app);
/// Adds `ppp experiment`: the full experiment with resume and report.
void addExperimentCommand(CLI::App& app);
/// Adds `ppp compare`: Mann-Whitney comparison of two sets' pass rates.
void addCompareCommand(CLI::App& app);
/// Adds `ppp launch-file`: the roslaunch XML of an experiment's ROS graph.
void addLaunchFileCommand(CLI::App& app);
/// Adds `ppp options`: the reference of every declared option (docs/reference/options.md).
void addOptionsCommand(CLI::App& app);

}  // namespace cli
}  // namespace ppp
