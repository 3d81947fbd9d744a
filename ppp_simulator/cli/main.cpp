// `ppp`: PPP Lab's command line. Each subcommand is a thin call into the ROS-free libraries.
#include <iostream>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "ppp_core/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"ppp: evolve, evaluate, convert and simulate path-planning problems (PPPs)"};
  app.require_subcommand(1);
  ppp::cli::addRandomCommand(app);
  ppp::cli::addEvaluateCommand(app);
  ppp::cli::addConvertCommand(app);
  ppp::cli::addGenerateCommand(app);
  ppp::cli::addTreeCommand(app);
  ppp::cli::addSelectCommand(app);
  ppp::cli::addSimulateCommand(app);
  ppp::cli::addReplayCommand(app);
  ppp::cli::addExperimentCommand(app);
  ppp::cli::addCompareCommand(app);
  ppp::cli::addLaunchFileCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const ppp::Error& e) {
    std::cerr << "ppp: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "ppp: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
