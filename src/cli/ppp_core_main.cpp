// `ppp-core`: the ROS-free core's command line (random, evaluate, convert), built with the core alone; the
// workspace's `ppp` has these subcommands too.
#include "core_commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"ppp-core: draw, evaluate and convert path-planning problems (PPPs) with the ROS-free core"};
  ppp::cli::addCoreCommands(app);
  return ppp::cli::runCommandLine(app, argc, argv, "ppp-core");
}
