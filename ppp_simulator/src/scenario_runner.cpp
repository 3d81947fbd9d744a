#include "ppp_simulator/scenario_runner.hpp"

#include <algorithm>
#include <map>
#include <memory>

#include "ppp_core/error.hpp"
#include "ppp_core/movingai_map.hpp"
#include "ppp_core/optimum.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace simulator {

namespace {

/// A map of the scenario file, read once: its grid, a problem on it whose start and goal each scenario sets, and
/// the episode runner with the budget for it.
struct LoadedMap {
  Grid grid;
  Problem problem;
  int budget;
  std::unique_ptr<agents::EpisodeRunner> runner;
};

}  // namespace

int scenarioBudget(const Grid& grid) {
  const long free_cells = static_cast<long>(grid.size()) - grid.obstacleCount();
  return static_cast<int>(std::clamp<long>(free_cells, 1, kMaxEpisodeBudget));
}

std::vector<ScenarioResult> runScenarios(const std::string& scen_path, const ScenarioRunOptions& options) {
  const std::vector<MovingAiScenario> scenarios = readMovingAiScenarios(scen_path);
  const std::unique_ptr<agents::Agent> agent = agents::makeAgent(options.agent);
  std::map<std::string, std::string> paths;  // the path found, by the map's name in the file
  std::map<std::string, LoadedMap> maps;     // by the path found
  std::vector<ScenarioResult> results;
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    const MovingAiScenario& s = scenarios[i];
    auto named = paths.find(s.map);
    if (named == paths.end()) named = paths.emplace(s.map, findScenarioMap(scen_path, s.map, options.map_dir)).first;
    auto found = maps.find(named->second);
    if (found == maps.end()) {
      Problem problem = readMovingAiMap(named->second);
      Grid grid = decodeGrid(problem);  // the map as drawn: the default start and goal are free cells
      EpisodeOptions episode = options.episode;
      if (!options.budget_given) episode.budget = scenarioBudget(grid);
      auto runner = std::make_unique<agents::EpisodeRunner>(options.agent, episode);
      found = maps.emplace(named->second, LoadedMap{std::move(grid), std::move(problem), episode.budget,
                                                    std::move(runner)}).first;
    }
    LoadedMap& map = found->second;
    checkScenarioOnMap(s, map.grid, scen_path);
    // Start and goal are free cells of the map, so protecting them changes no cell: the grid stays the map's.
    map.problem.start = s.start;
    map.problem.goal = s.goal;
    ScenarioResult result;
    result.scenario = s;
    result.seed = deriveSeed(options.seed, {static_cast<std::uint64_t>(i)});
    result.budget = options.episode.budget_factor > 0 ? episodeBudget(options.episode, map.problem, map.grid) : map.budget;
    result.outcome = map.runner->run(map.problem, map.grid, *agent, result.seed);
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace simulator
}  // namespace ppp
