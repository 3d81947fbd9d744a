#include <algorithm>
#include <iostream>
#include <memory>
#include <string>

#include "cli_options.hpp"
#include "core_commands.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/evaluation.hpp"
#include "ppp_core/problem_io.hpp"
#include "ppp_core/random_problem.hpp"

namespace ppp {
namespace cli {

namespace {

struct RandomOptions {
  std::string size = "20x20";
  int obstacles = 0;
  int max_obstacles = -1;
  std::uint64_t seed = 0;
  std::string start;
  std::string goal;
  std::string output;
};

void runRandom(const RandomOptions& o) {
  const Size size = parseSize(o.size, "--size");
  if (o.obstacles < 0) throw InvalidArgument("--obstacles", "expected a count >= 0, got " + std::to_string(o.obstacles));
  Problem shape = Problem::empty(size.width, size.height, o.max_obstacles >= 0 ? o.max_obstacles : std::max(o.obstacles, 10));
  if (!o.start.empty()) shape.start = parseCell(o.start, "--start");
  if (!o.goal.empty()) shape.goal = parseCell(o.goal, "--goal");
  Rng rng(o.seed);
  Problem problem = randomProblem(rng, shape, o.obstacles);
  setMetadata(&problem.metadata, "generator", "random");
  setMetadata(&problem.metadata, "seed", std::to_string(o.seed));
  writeProblemFile(problem, o.output);
  Evaluator evaluator;
  const Evaluation e = evaluator.evaluate(problem);
  std::cout << "wrote " << o.output << ": " << problem.width << "x" << problem.height << ", "
            << problem.obstacles.size() << " obstacles, " << e.turns << " turns, " << e.advances << " advances\n";
}

}  // namespace

void addRandomCommand(CLI::App& app) {
  auto options = std::make_shared<RandomOptions>();
  CLI::App* command = app.add_subcommand("random", "Draw a random solvable PPP (unsolvable draws are redrawn)");
  command->add_option("--size", options->size, "Grid size WIDTHxHEIGHT")->capture_default_str();
  command->add_option("--obstacles", options->obstacles, "Number of random obstacle descriptors")->required();
  command->add_option("--max-obstacles", options->max_obstacles,
                      "Obstacle budget stored in the PPP (default: the larger of --obstacles and 10)");
  command->add_option("--seed", options->seed, "Seed of the random generator")->required();
  command->add_option("--start", options->start, "Start cell X,Y (default 0,0: top-left)");
  command->add_option("--goal", options->goal, "Goal cell X,Y (default bottom-right)");
  command->add_option("-o,--output", options->output, "Output file: .ppp, .yaml, .png, .bt or .map")->required();
  command->callback([options] { runRandom(*options); });
}

}  // namespace cli
}  // namespace ppp
