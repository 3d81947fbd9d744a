#include "ppp_agents/prepared_set.hpp"

#include <utility>

#include "ppp_core/dpa.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/octile.hpp"

namespace ppp {
namespace agents {

EpisodeResult episodeResult(const PreparedSet& set, int problem, const std::string& agent, int run,
                            std::uint64_t seed, const EpisodeOutcome& outcome) {
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
  r.reason = outcome.reason;
  return r;
}

PreparedSet prepareSet(const std::string& name, ProblemSet set, const EpisodeOptions& episode) {
  const int sensor_range = episode.sensor_range;
  PreparedSet p;
  p.name = name;
  p.set = std::move(set);
  DpaSolver dpa;
  for (const Problem& problem : p.set.problems) {
    p.grids.push_back(decodeGrid(problem));
    const DpaResult& result = dpa.solve(p.grids.back(), problem.start, problem.goal);
    if (!result.reachable) throw InvalidArgument("sets", "set '" + name + "' holds an unsolvable PPP");
    p.optimal.push_back(episode.connectivity == Connectivity::Eight
                            ? shortestOctileRoute(p.grids.back(), problem.start, problem.goal).length
                            : static_cast<double>(result.advances));
    p.windows.push_back(WindowAtlas::bytes(p.grids.back(), sensor_range) <= kMaxWindowAtlasBytes
                            ? std::optional<WindowAtlas>(std::in_place, p.grids.back(), sensor_range)
                            : std::nullopt);
  }
  return p;
}

}  // namespace agents
}  // namespace ppp
