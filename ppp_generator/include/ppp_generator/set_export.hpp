#pragma once

#include <string>
#include <vector>

#include "ppp_core/movingai_scen.hpp"
#include "ppp_generator/problem_set.hpp"

namespace ppp {
namespace generator {

/// File extensions a set can be exported to, each written by ppp_core's writeProblemFile.
const std::vector<std::string>& exportExtensions();

/// The MovingAI scenarios of a set, one per PPP in set order: map `<id>.map`, its size, start and goal, and the
/// optimal 8-connected length (1 per straight move, sqrt(2) per diagonal, no corner cutting: the benchmark's
/// convention, not the PPP's own 4-connected one); bucket = floor(length / 4), as in the benchmark's files.
std::vector<MovingAiScenario> setScenarios(const ProblemSet& set);

/// Writes every PPP of `set` into the existing directory `dir` as `<id><extension>` (one of exportExtensions());
/// for ".map" also `<scenario_name>.scen` with setScenarios(). Returns the paths written, in set order, the .scen
/// last. @throws InvalidArgument("--format", ...) for another extension; IoError from the writers.
std::vector<std::string> exportProblemSet(const ProblemSet& set, const std::string& dir, const std::string& extension,
                                          const std::string& scenario_name);

}  // namespace generator
}  // namespace ppp
