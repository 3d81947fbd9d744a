#include "ppp_generator/initial_pool.hpp"

#include "ppp_core/error.hpp"
#include "ppp_core/problem_io.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_generator/problem_set.hpp"

namespace ppp {
namespace generator {

namespace {

/// Why `problem` cannot join a pool evolved with `options`, or "" when it can.
std::string mismatch(const Problem& problem, const GeneratorOptions& options) {
  if (problem.width != options.width || problem.height != options.height) {
    return std::to_string(problem.width) + "x" + std::to_string(problem.height) + " grid, expected the generator's " +
           std::to_string(options.width) + "x" + std::to_string(options.height);
  }
  if (problem.start != options.startCell()) {
    return "start " + cellText(problem.start) + ", expected the generator's " + cellText(options.startCell());
  }
  if (problem.goal != options.goalCell()) {
    return "goal " + cellText(problem.goal) + ", expected the generator's " + cellText(options.goalCell());
  }
  if (static_cast<int>(problem.obstacles.size()) > options.max_obstacles) {
    return std::to_string(problem.obstacles.size()) + " obstacle descriptors, more than max_obstacles " +
           std::to_string(options.max_obstacles);
  }
  return "";
}

}  // namespace

std::vector<Individual> initialPoolIndividuals(const GeneratorOptions& options, Breeder* breeder) {
  if (options.initial_pool.empty()) return {};
  std::vector<std::string> files;
  try {
    files = problemSetFiles(options.initial_pool);
  } catch (const Error& e) {
    throw InvalidArgument("initial_pool", e.what());
  }
  std::vector<Individual> pool;
  for (const std::string& file : files) {
    if (static_cast<int>(pool.size()) == options.population) break;
    Individual individual;
    individual.problem = readProblemFile(file);
    const std::string why = mismatch(individual.problem, options);
    if (!why.empty()) throw InvalidArgument("initial_pool", file + ": " + why);
    individual.problem.max_obstacles = options.max_obstacles;
    if (!breeder->decode(&individual)) {
      throw InvalidArgument("initial_pool", file + ": the goal is out of reach for the robot (robot_radius " +
                                                formatShortest(options.robot_radius) + ")");
    }
    if (!gridInPool(pool, individual)) pool.push_back(std::move(individual));
  }
  return pool;
}

}  // namespace generator
}  // namespace ppp
