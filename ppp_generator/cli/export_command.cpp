#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "generator_commands.hpp"
#include "ppp_core/error.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_generator/set_export.hpp"

namespace ppp {
namespace cli {

namespace {

struct ExportFlags {
  std::string dir;
  std::string output;
  std::string format = "map";
};

void runExport(const ExportFlags& f) {
  const ProblemSet set = generator::readProblemSetDirectory(f.dir);
  std::error_code error;
  std::filesystem::create_directories(f.output, error);
  if (error) throw IoError(f.output, "cannot create the directory: " + error.message());
  const std::string name = std::filesystem::path(f.dir).lexically_normal().filename().string();
  const std::vector<std::string> written =
      generator::exportProblemSet(set, f.output, "." + f.format, name.empty() ? "set" : name);
  std::cerr << "wrote " << written.size() << " files to " << f.output
            << (f.format == "map" ? " (" + std::to_string(set.problems.size()) + " .map files and " + written.back() + ")"
                                  : std::string())
            << "\n";
}

}  // namespace

void addExportCommand(CLI::App& app) {
  auto flags = std::make_shared<ExportFlags>();
  CLI::App* command = app.add_subcommand(
      "export", "Write every PPP of a set in another format; as MovingAI .map files, also a .scen of their "
                "start/goal pairs and optimal 8-connected lengths");
  command->add_option("dir", flags->dir, "Set directory written by ppp generate")->required();
  command->add_option("output", flags->output, "Directory to write into (created if missing)")->required();
  command->add_option("--format", flags->format, "map (MovingAI, plus SET.scen), ppp, yaml (+pgm), png or bt")
      ->capture_default_str();
  command->callback([flags] { runExport(*flags); });
}

}  // namespace cli
}  // namespace ppp
