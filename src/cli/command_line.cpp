#include <iostream>

#include "core_commands.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/stop.hpp"

namespace ppp {
namespace cli {

int runCommandLine(CLI::App& app, int argc, char** argv, const char* program) {
  app.require_subcommand(1);
  app.name(program);  // the usage lines say `ppp simulate`, not the binary's path (docs/reference/cli.md quotes them)
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const Interrupted&) {
    std::cerr << program << ": interrupted; everything finished is written and nothing half-done is. Rerun the "
                            "same command to go on.\n";
    return 130;
  } catch (const Error& e) {
    std::cerr << program << ": error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << program << ": internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}

}  // namespace cli
}  // namespace ppp
