#include <iostream>
#include <memory>
#include <string>

#include "cli_options.hpp"
#include "core_commands.hpp"
#include "ppp_core/dpa.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/problem_io.hpp"

namespace ppp {
namespace cli {

namespace {

struct ConvertOptions {
  std::string input;
  std::string output;
  double resolution = 1.0;
  double height = 1.0;
  int cell_pixels = 16;
  bool no_grid_lines = false;
  bool route = false;
  std::string start;
  std::string goal;
};

void runConvert(const ConvertOptions& o) {
  MapImportOptions import;
  if (!o.start.empty()) import.start = parseCell(o.start, "--start");
  if (!o.goal.empty()) import.goal = parseCell(o.goal, "--goal");
  const Problem problem = readProblemFile(o.input, import);
  ProblemWriteOptions write;
  write.map.resolution = o.resolution;
  write.octomap.resolution = o.resolution;
  write.octomap.height = o.height;
  write.picture.cell_pixels = o.cell_pixels;
  write.picture.grid_lines = !o.no_grid_lines;
  if (o.route) {
    const DpaResult dpa = solveDpa(decodeGrid(problem), problem.start, problem.goal);
    if (!dpa.reachable) throw InvalidArgument("--route", "the goal of " + o.input + " is unreachable: no route");
    write.path = dpa.route;
  }
  writeProblemFile(problem, o.output, write);
  std::cout << "wrote " << o.output << "\n";
}

}  // namespace

void addConvertCommand(CLI::App& app) {
  auto options = std::make_shared<ConvertOptions>();
  CLI::App* command = app.add_subcommand(
      "convert",
      "Convert a PPP between .ppp, map_server .yaml (+.pgm), MovingAI .map, .png and OctoMap .bt (by extension)");
  command->add_option("input", options->input, "Input: .ppp, .yaml or .map")->required();
  command->add_option("output", options->output, "Output: .ppp, .yaml, .map, .png or .bt")->required();
  command->add_option("--resolution", options->resolution, "Metres per cell for .yaml and .bt")
      ->capture_default_str();
  command->add_option("--height", options->height, "Height in metres obstacles are extruded to in .bt")
      ->capture_default_str();
  command->add_option("--cell-pixels", options->cell_pixels, "Pixels per cell in .png")->capture_default_str();
  command->add_flag("--no-grid-lines", options->no_grid_lines, "Leave out the cell grid lines in .png");
  command->add_flag("--route", options->route, "Draw the fewest turns+advances route in .png");
  command->add_option("--start", options->start,
                      "Start cell X,Y when importing a foreign map (.yaml: default 0,0; .map: the first free cell)");
  command->add_option("--goal", options->goal,
                      "Goal cell X,Y when importing a foreign map (.yaml: default bottom-right; .map: the last free "
                      "cell)");
  command->callback([options] { runConvert(*options); });
}

}  // namespace cli
}  // namespace ppp
