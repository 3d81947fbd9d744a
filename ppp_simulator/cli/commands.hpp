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
/// Adds `ppp simulate`: one agent, many runs, one PPP.
void addSimulateCommand(CLI::App& app);
/// Adds `ppp replay`: one episode drawn as a picture.
void addReplayCommand(CLI::App& app);
/// Adds `ppp experiment`: the full experiment with resume and report.
void addExperimentCommand(CLI::App& app);
/// Adds `ppp launch-file`: the roslaunch XML of an experiment's ROS graph.
void addLaunchFileCommand(CLI::App& app);
/// Adds `ppp compare`: Mann-Whitney comparison of two sets' pass rates.
void addCompareCommand(CLI::App& app);

}  // namespace cli
}  // namespace ppp
