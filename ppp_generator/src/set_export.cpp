#include "ppp_generator/set_export.hpp"

#include <algorithm>
#include <cmath>

#include "ppp_core/error.hpp"
#include "ppp_core/octile.hpp"
#include "ppp_core/problem_io.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {
namespace generator {

namespace {

constexpr double kBucketWidth = 4;  // the benchmark's scenario buckets: optimal length / 4

}  // namespace

const std::vector<std::string>& exportExtensions() {
  static const std::vector<std::string> extensions = {".ppp", ".yaml", ".map", ".png", ".bt"};
  return extensions;
}

std::vector<MovingAiScenario> setScenarios(const ProblemSet& set) {
  std::vector<MovingAiScenario> scenarios;
  for (std::size_t i = 0; i < set.problems.size(); ++i) {
    const Problem& p = set.problems[i];
    MovingAiScenario s;
    s.map = set.ids[i] + ".map";
    s.map_width = p.width;
    s.map_height = p.height;
    s.start = p.start;
    s.goal = p.goal;
    s.optimal_length = shortestOctileRoute(decodeGrid(p), p.start, p.goal).length;
    s.bucket = static_cast<int>(std::floor(s.optimal_length / kBucketWidth));
    scenarios.push_back(s);
  }
  return scenarios;
}

std::vector<std::string> exportProblemSet(const ProblemSet& set, const std::string& dir, const std::string& extension,
                                          const std::string& scenario_name) {
  const std::vector<std::string>& valid = exportExtensions();
  if (std::find(valid.begin(), valid.end(), extension) == valid.end()) {
    throw InvalidArgument("--format", "cannot export to '" + extension + "'; valid: " + joinNames(valid));
  }
  std::vector<std::string> written;
  for (std::size_t i = 0; i < set.problems.size(); ++i) {
    written.push_back(dir + "/" + set.ids[i] + extension);
    writeProblemFile(set.problems[i], written.back());
  }
  if (extension == ".map") {
    written.push_back(dir + "/" + scenario_name + ".scen");
    writeMovingAiScenarios(setScenarios(set), written.back());
  }
  return written;
}

}  // namespace generator
}  // namespace ppp
