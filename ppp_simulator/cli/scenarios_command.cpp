#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "agent_flags.hpp"
#include "commands.hpp"
#include "ppp_core/csv.hpp"
#include "ppp_simulator/scenario_runner.hpp"

namespace ppp {
namespace cli {

namespace {

struct ScenariosFlags {
  AgentFlags agent;
  std::string scen;
  std::string map_dir;
  std::uint64_t seed = 1;
  bool json = false;
};

nlohmann::json cellJson(Cell c) { return nlohmann::json::array({c.x, c.y}); }

void runScenariosCommand(const ScenariosFlags& f) {
  simulator::ScenarioRunOptions options;
  options.agent = f.agent.agent();
  options.episode = f.agent.episode();
  options.budget_given = f.agent.given(flagName(optionNamed(episodeOptionSpecs(), "budget")));
  options.seed = f.seed;
  options.map_dir = f.map_dir;
  const std::vector<simulator::ScenarioResult> results = simulator::runScenarios(f.scen, options);
  long passed = 0;
  double path_total = 0;
  double optimal_total = 0;  // over the passed scenarios
  nlohmann::json list = nlohmann::json::array();
  for (const simulator::ScenarioResult& r : results) {
    const MovingAiScenario& s = r.scenario;
    if (r.outcome.passed) {
      ++passed;
      path_total += pathLength(r.outcome);
      optimal_total += s.optimal_length;
    }
    list.push_back({{"bucket", s.bucket},
                    {"start", cellJson(s.start)},
                    {"goal", cellJson(s.goal)},
                    {"optimal_length", s.optimal_length},
                    {"path_length", pathLength(r.outcome)},
                    {"passed", r.outcome.passed},
                    {"steps", r.outcome.steps},
                    {"seed", r.seed}});
  }
  const double ratio = optimal_total > 0 ? path_total / optimal_total : 0;
  if (f.json) {
    const nlohmann::json j = {{"agent", options.agent.name},
                              {"connectivity", neighbours(options.episode.connectivity)},
                              {"scenarios", list},
                              {"totals",
                               {{"scenarios", results.size()},
                                {"passed", passed},
                                {"path_length", path_total},
                                {"optimal_length", optimal_total}}}};
    std::cout << j.dump() << "\n";
    return;
  }
  std::cout << options.agent.name << " on " << f.scen << ": " << passed << " of " << results.size()
            << " scenarios passed; over those, path length / published optimal length = " << formatNumber(ratio)
            << (options.episode.connectivity == Connectivity::Eight ? " (8-connected moves)\n"
                                                  : " (4-connected moves against the benchmark's 8-connected optima; "
                                                    "--connectivity 8 plays the benchmark's model)\n");
}

}  // namespace

void addScenariosCommand(CLI::App& app) {
  auto flags = std::make_shared<ScenariosFlags>();
  CLI::App* command = app.add_subcommand(
      "scenarios", "Run one agent once on every scenario of a MovingAI .scen file and compare its path length with "
                   "the published optimal length (--connectivity 8: the benchmark's move model; only astar "
                   "takes diagonal moves)");
  command->add_option("scen", flags->scen, "MovingAI scenario file (version 1)")->required();
  flags->agent.add(command);
  command->add_option("--map-dir", flags->map_dir,
                      "Where else to look for the maps (first: the path in the file, then beside the .scen)");
  command->add_option("--seed", flags->seed, "Seed; scenario i runs with a seed derived from it")
      ->capture_default_str();
  command->add_flag("--json", flags->json,
                    "Print {agent, connectivity, scenarios: [{bucket, start, goal, optimal_length, path_length, "
                    "passed, steps, seed}], totals} as JSON");
  command->footer(
      "Without --budget, a scenario's budget is its map's free cells (every simple path fits; at most 1,000,000).");
  command->callback([flags] { runScenariosCommand(*flags); });
}

}  // namespace cli
}  // namespace ppp
