#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli_options.hpp"
#include "core_commands.hpp"
#include "ppp_core/barn_metrics.hpp"
#include "ppp_core/csv.hpp"
#include "ppp_core/evaluation_json.hpp"
#include "ppp_core/problem_io.hpp"

namespace ppp {
namespace cli {

namespace {

struct EvaluateOptions {
  std::vector<std::string> files;
  bool json = false;
  std::string csv;
  std::vector<std::string> weights;
};

void printText(const std::string& file, const Problem& p, const Evaluation& e) {
  std::cout << file << ": " << p.width << "x" << p.height << ", " << (e.valid ? "valid" : "INVALID (goal unreachable)")
            << "\n";
  if (e.valid) {
    std::cout << "  turns " << e.turns << ", advances " << e.advances << ", turns+advances "
              << e.turns_plus_advances << "\n";
  }
  std::cout << "  obstacles " << e.obstacles << " of " << p.max_obstacles << " (use " << formatNumber(e.obstacle_use)
            << ")\n"
            << "  visibility start " << formatNumber(e.visibility.start) << ", goal "
            << formatNumber(e.visibility.goal) << ", centre " << formatNumber(e.visibility.centre) << ", top-right "
            << formatNumber(e.visibility.top_right) << ", bottom-left " << formatNumber(e.visibility.bottom_left)
            << "\n"
            << "  openness horizontal " << formatNumber(e.horizontal_openness) << ", vertical "
            << formatNumber(e.vertical_openness) << "\n"
            << "  difficulty " << formatNumber(e.difficulty) << " (lower is harder)\n";
}

void runEvaluate(const EvaluateOptions& o) {
  Evaluator evaluator(parseWeights(o.weights));
  DpaSolver dpa_solver;
  std::optional<CsvWriter> csv;
  if (!o.csv.empty()) {
    std::vector<std::string> header{"file", "width", "height", "valid"};
    for (const auto& name : characterNames()) header.push_back(name);
    csv.emplace(o.csv, header);
  }
  for (const std::string& file : o.files) {
    const Problem problem = readProblemFile(file);
    const Grid grid = decodeGrid(problem);
    const DpaResult& dpa = dpa_solver.solve(grid, problem.start, problem.goal);  // one DPA for both
    const Evaluation e = evaluator.evaluate(problem, grid, dpa);
    if (o.json) {
      nlohmann::json j = evaluationToJson(problem, e);
      j["barn"] = barnMetricsToJson(barnMetrics(grid, dpa));
      std::cout << j.dump() << "\n";
    } else if (!csv) {
      printText(file, problem, e);
    }
    if (csv) {
      std::vector<std::string> row{file, std::to_string(problem.width), std::to_string(problem.height),
                                   e.valid ? "1" : "0"};
      for (double value : characterVector(e)) row.push_back(formatNumber(value));
      csv->write(row);
    }
  }
}

}  // namespace

void addEvaluateCommand(CLI::App& app) {
  auto options = std::make_shared<EvaluateOptions>();
  CLI::App* command =
      app.add_subcommand("evaluate", "Ashlock's DPA, visibility, openness and the difficulty score of PPP files");
  command->add_option("files", options->files, "PPP files (.ppp, map_server .yaml or MovingAI .map)")->required();
  command->add_flag("--json", options->json, "One JSON object per file, one per line, BARN's metrics under \"barn\"");
  command->add_option("--csv", options->csv, "Also write one CSV row of characters per file to this path");
  command->add_option("--weight", options->weights,
                      "Difficulty weight override NAME=VALUE (start, centre, top_right, bottom_left, goal, "
                      "unused_obstacles, horizontal_openness, vertical_openness, one_turn_penalty); repeatable");
  command->callback([options] { runEvaluate(*options); });
}

}  // namespace cli
}  // namespace ppp
