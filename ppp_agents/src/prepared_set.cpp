#include "ppp_agents/prepared_set.hpp"

#include <algorithm>
#include <utility>

#include "ppp_core/error.hpp"
#include "ppp_core/footprint.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_core/optimum.hpp"
#include "ppp_core/reachability.hpp"

namespace ppp {
namespace agents {

EpisodeResult episodeResult(const PreparedSet& set, int problem, const std::string& agent, int run,
                            std::uint64_t seed, const EpisodeOutcome& outcome,
                            const std::vector<std::uint64_t>& states, const char* reported_kind) {
  EpisodeResult r;
  r.set = set.name;
  r.problem = set.set.ids[problem];
  r.agent = agent;
  r.run = run;
  r.seed = seed;
  r.passed = outcome.passed;
  r.steps = outcome.steps;
  r.bumps = outcome.bumps;
  r.path_length = pathLength(outcome);
  r.optimal_length = set.optimal[problem];
  r.soft_failure = isSoftFailure(r.passed, r.path_length, r.optimal_length, set.episode.soft_failure_ratio);
  r.reason = outcome.reason;
  setDiagnosisAndSignature(set, problem, diagnoseRun(r.passed, r.soft_failure, r.reason, outcome.cells, states, reported_kind),
                           outcome.cells, &r);
  return r;
}

void setDiagnosisAndSignature(const PreparedSet& set, int problem, const Diagnosis& d, const std::vector<Cell>& cells,
                              EpisodeResult* result) {
  setDiagnosis(d, result);
  result->signature = failureSignature(set.signature_maps[static_cast<std::size_t>(problem)], d, result->reason, cells);
}

int largestActionLimit(const std::vector<PreparedSet>& sets) {
  long largest = 0;
  for (const PreparedSet& set : sets) {
    for (const int budget : set.budgets) largest = std::max(largest, set.episode.budgetRule(budget).actionLimit());
  }
  return static_cast<int>(largest);
}

PreparedSet prepareSet(const std::string& name, ProblemSet set, const EpisodeOptions& episode) {
  const int sensor_range = episode.sensor_range;
  PreparedSet p;
  p.name = name;
  p.set = std::move(set);
  p.episode = episode;
  for (const Problem& problem : p.set.problems) {
    p.grids.push_back(decodeGrid(problem));
    if (!isPointRobot(episode.robot_radius)) p.spaces.push_back(configurationSpace(p.grids.back(), episode.robot_radius));
    const Grid& motion = p.spaces.empty() ? p.grids.back() : p.spaces.back();
    // Every agent but astar moves 4-connected, so a PPP must be solvable that way whatever the move model.
    if (!isReachable(motion, problem.start, problem.goal)) {
      throw InvalidArgument("sets", "set '" + name + "' holds a PPP (" + p.set.ids[p.grids.size() - 1] +
                                        ") unsolvable" + (p.spaces.empty() ? "" : " for a robot of radius " +
                                        formatShortest(episode.robot_radius)));
    }
    const Optimum optimum = optimumOf(problem, motion, episode.connectivity);
    p.optimal.push_back(optimum.length);
    p.moves.push_back(optimum.moves);
    p.budgets.push_back(episodeBudget(episode, optimum.moves));
    p.signature_maps.emplace_back(p.grids.back(), motion, problem.start, problem.goal);
    p.windows.push_back(WindowAtlas::bytes(p.grids.back(), sensor_range) <= kMaxWindowAtlasBytes
                            ? std::optional<WindowAtlas>(std::in_place, p.grids.back(), sensor_range)
                            : std::nullopt);
  }
  return p;
}

PreparedSet prepareSingle(const std::string& name, const std::string& id, const Problem& problem,
                          const EpisodeOptions& episode) {
  ProblemSet single;
  single.ids = {id};
  single.problems = {problem};
  return prepareSet(name, std::move(single), episode);
}

}  // namespace agents
}  // namespace ppp
