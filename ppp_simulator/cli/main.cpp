// `ppp`: PPP Lab's command line, one binary for the workspace: the core's subcommands (src/cli), the generator's
// (ppp_generator/cli) and the simulator's (here), each a thin call into its ROS-free library.
#include "commands.hpp"
#include "core_commands.hpp"
#include "generator_commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"ppp: evolve, evaluate, convert and simulate path-planning problems (PPPs)"};
  ppp::cli::addCoreCommands(app);
  ppp::cli::addGeneratorCommands(app);
  ppp::cli::addSimulateCommand(app);
  ppp::cli::addReplayCommand(app);
  ppp::cli::addShrinkCommand(app);
  ppp::cli::addCheckCommand(app);
  ppp::cli::addScenariosCommand(app);
  ppp::cli::addExperimentCommand(app);
  ppp::cli::addCompareCommand(app);
  ppp::cli::addLaunchFileCommand(app);
  ppp::cli::addOptionsCommand(app);
  return ppp::cli::runCommandLine(app, argc, argv, "ppp");
}
