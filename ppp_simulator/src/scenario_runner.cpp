#include "ppp_simulator/scenario_runner.hpp"

#include <algorithm>
#include <map>
#include <memory>

#include "ppp_core/error.hpp"
#include "ppp_core/movingai_map.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace simulator {

namespace {

/// A map of the scenario file, read once: its grid and a problem on it whose start and goal each scenario sets.
struct LoadedMap {
  Grid grid;
  Problem problem;
};

}  // namespace

int scenarioBudget(const Grid& grid) {
  const long free_cells = static_cast<long>(grid.size()) - grid.obstacleCount();
  return static_cast<int>(std::clamp<long>(free_cells, 1, kMaxEpisodeBudget));
}

std::vector<ScenarioResult> runScenarios(const std::string& scen_path, const ScenarioRunOptions& options) {
  const std::vector<MovingAiScenario> scenarios = readMovingAiScenarios(scen_path);
  const std::unique_ptr<agents::Agent> agent = agents::makeAgent(options.agent);
  std::map<std::string, LoadedMap> maps;  // by the path found
  std::vector<ScenarioResult> results;
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    const MovingAiScenario& s = scenarios[i];
    const std::string path = findScenarioMap(scen_path, s.map, options.map_dir);
    auto found = maps.find(path);
    if (found == maps.end()) {
      Problem problem = readMovingAiMap(path);
      Grid grid = decodeGrid(problem);  // the map as drawn: the default start and goal are free cells
      found = maps.emplace(path, LoadedMap{std::move(grid), std::move(problem)}).first;
    }
    LoadedMap& map = found->second;
    checkScenarioOnMap(s, map.grid, scen_path);
    if (s.start == s.goal) throw ParseError(scen_path, s.line, "goal", "equals the start");
    // Start and goal are free cells of the map, so protecting them changes no cell: the grid stays the map's.
    map.problem.start = s.start;
    map.problem.goal = s.goal;
    EpisodeOptions episode = options.episode;
    if (!options.budget_given) episode.budget = scenarioBudget(map.grid);
    EpisodeRunner runner(options.agent, episode);
    ScenarioResult result;
    result.scenario = s;
    result.seed = deriveSeed(options.seed, {static_cast<std::uint64_t>(i)});
    result.budget = episode.budget;
    result.outcome = runner.run(map.problem, map.grid, *agent, result.seed);
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace simulator
}  // namespace ppp
