#include "ppp_generator/initial_pool.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "ppp_core/error.hpp"
#include "ppp_core/ppp_file.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {
namespace generator {

namespace fs = std::filesystem;

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

/// The `.ppp` files of a directory, in file-name order. @throws IoError when it is not a readable directory.
std::vector<std::string> pppFilesIn(const std::string& dir) {
  std::error_code error;
  if (!fs::is_directory(dir, error)) throw IoError(dir, "is not a directory of .ppp files");
  std::vector<std::string> files;
  for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
    if (it->path().extension() == ".ppp" && it->is_regular_file(error)) files.push_back(it->path().string());
  }
  if (error) throw IoError(dir, "cannot list it: " + error.message());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

std::vector<Individual> initialPoolIndividuals(const GeneratorOptions& options, Breeder* breeder) {
  if (options.initial_pool.empty()) return {};
  std::vector<std::string> files;
  try {
    files = pppFilesIn(options.initial_pool);
  } catch (const IoError& e) {
    throw InvalidArgument("initial_pool", e.what());
  }
  if (files.empty()) throw InvalidArgument("initial_pool", options.initial_pool + " holds no .ppp file");
  std::vector<Individual> pool;
  for (const std::string& file : files) {
    if (static_cast<int>(pool.size()) == options.population) break;
    Individual individual;
    individual.problem = readPppFile(file);
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
