#include <iostream>
#include <map>

#include "core_commands.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/stop.hpp"

namespace ppp {
namespace cli {

namespace {

std::map<const CLI::App*, int>& usageErrorStatuses() {
  static std::map<const CLI::App*, int> statuses;
  return statuses;
}

}  // namespace

void setUsageErrorStatus(const CLI::App* command, int status) { usageErrorStatuses()[command] = status; }

int runCommandLine(CLI::App& app, int argc, char** argv, const char* program) {
  app.require_subcommand(1);
  app.name(program);  // the usage lines say `ppp simulate`, not the binary's path (docs/reference/cli.md quotes them)
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int status = app.exit(e);
    if (dynamic_cast<const CLI::RuntimeError*>(&e) != nullptr) return status;  // a command's own status
    for (const CLI::App* command : app.get_subcommands()) {
      const auto found = usageErrorStatuses().find(command);
      if (status != 0 && found != usageErrorStatuses().end()) return found->second;
    }
    return status;
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
