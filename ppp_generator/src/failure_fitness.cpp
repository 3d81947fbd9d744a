#include "ppp_generator/failure_fitness.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "ppp_agents/episode_runner.hpp"
#include "ppp_core/diagnosis.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/failure_signature.hpp"
#include "ppp_core/footprint.hpp"
#include "ppp_core/optimum.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_core/window_atlas.hpp"

namespace ppp {
namespace generator {

namespace {

void checkPanel(const std::vector<agents::AgentConfig>& panel) {
  if (panel.empty()) throw InvalidArgument("agents", "empty panel: a panel fitness (failure, regret) needs at least one agent");
  for (const agents::AgentConfig& a : panel) {
    if (agents::isPlanner(a)) {
      throw InvalidArgument("agents", "'" + a.name + "' is a ROS planner agent; in process a hunt can only run "
                                      "built-in agents (hunt a planner with launch/hunt.launch)");
    }
    a.validate();
  }
}

}  // namespace

std::uint64_t failureRunSeed(std::uint64_t generator_seed, std::uint64_t grid_hash, const std::string& agent,
                             int run) {
  return deriveSeed(generator_seed, {0x6661696c, grid_hash, nameHash(agent), static_cast<std::uint64_t>(run)});
}

void PanelTally::add(std::size_t agent, bool passed, int run_steps, int budget, int optimal_moves) {
  failures[agent] += passed ? 0 : 1;
  // A run that ended before its budget without reaching the goal (timeout, lost agent) used its whole budget; a
  // passed run with free stays or bumps (more actions than the budget) uses no more than all of it.
  const int used = std::min(run_steps, budget);
  steps[agent] += passed ? used : budget;
  regret[agent] += runRegret(passed, used, budget, optimal_moves);
}

FailureEstimate estimateOf(const PanelTally& tally, int runs, int budget) {
  FailureEstimate estimate;
  const double agents = static_cast<double>(tally.failures.size());
  for (std::size_t a = 0; a < tally.failures.size(); ++a) {
    estimate.failure_rate += tally.failures[a] / static_cast<double>(runs) / agents;
    estimate.budget_used += tally.steps[a] / (static_cast<double>(runs) * budget) / agents;
    estimate.regret += tally.regret[a] / runs / agents;
    estimate.steps += tally.played[a];
  }
  return estimate;
}

FitnessScore panelScore(const std::string& fitness, const FailureEstimate& estimate) {
  FitnessScore score = fitness == kRegretFitness ? regretScore(estimate.regret, estimate.budget_used)
                                                 : failureScore(estimate.failure_rate, estimate.budget_used);
  score.failure_rate = estimate.failure_rate;
  score.signatures = estimate.signatures;
  score.steps = estimate.steps;
  return score;
}

std::vector<FailureEstimate> estimateFailures(const FailurePanel& panel, const std::vector<const Problem*>& problems,
                                              const std::vector<const Grid*>& grids) {
  checkPanel(panel.agents);
  const std::size_t agent_count = panel.agents.size();
  const std::size_t units = problems.size() * agent_count;
  std::vector<PanelTally> tallies(problems.size(), PanelTally(agent_count));  // a worker owns a (PPP, agent) slot
  std::vector<std::uint64_t> hashes;
  std::vector<Optimum> optima;
  std::vector<int> budgets;
  std::vector<std::optional<WindowAtlas>> atlases(problems.size());
  std::vector<SignatureMap> signature_maps;
  std::vector<std::map<std::string, int>> signatures(units);  // per (PPP, agent) slot, as the tallies
  for (std::size_t p = 0; p < problems.size(); ++p) {
    hashes.push_back(grids[p]->hash());
    Grid space;
    const Grid& motion = motionGrid(*grids[p], panel.episode.robot_radius, &space);
    optima.push_back(optimumOf(*problems[p], motion, panel.episode.connectivity));
    if (panel.signatures) signature_maps.emplace_back(*grids[p], motion, problems[p]->start, problems[p]->goal);
    budgets.push_back(episodeBudget(panel.episode, optima.back().moves));
  }
  std::vector<std::once_flag> atlas_built(problems.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&]() {
    try {
      std::vector<std::unique_ptr<agents::Agent>> agents(agent_count);
      std::vector<std::unique_ptr<agents::EpisodeRunner>> runners(agent_count);
      for (;;) {
        const std::size_t u = next.fetch_add(1);
        if (u >= units) return;
        const std::size_t p = u / agent_count;
        const std::size_t a = u % agent_count;
        if (!agents[a]) {
          agents[a] = agents::makeAgent(panel.agents[a]);
          runners[a] = std::make_unique<agents::EpisodeRunner>(panel.agents[a], panel.episode);
        }
        const int range = panel.episode.sensor_range;
        std::call_once(atlas_built[p], [&] {
          if (WindowAtlas::bytes(*grids[p], range) <= kMaxWindowAtlasBytes) atlases[p].emplace(*grids[p], range);
        });
        const WindowAtlas* atlas = atlases[p] ? &*atlases[p] : nullptr;
        for (int run = 0; run < panel.runs_per_eval; ++run) {
          const std::uint64_t seed = failureRunSeed(panel.seed, hashes[p], panel.agents[a].name, run);
          const EpisodeOutcome outcome = runners[a]->run(*problems[p], *grids[p], *agents[a], seed, false, atlas);
          const bool soft = isSoftFailure(outcome.passed, pathLength(outcome), optima[p].length,
                                          panel.episode.soft_failure_ratio);
          tallies[p].add(a, outcome.passed && !soft, outcome.steps, budgets[p], optima[p].moves);
          tallies[p].played[a] += outcome.steps;
          if (panel.signatures && (!outcome.passed || soft)) {
            const Diagnosis d = diagnoseRun(outcome.passed, soft, outcome.reason, outcome.cells);
            ++signatures[u][failureSignature(signature_maps[p], d, outcome.reason, outcome.cells)];
          }
        }
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
    }
  };
  const int hardware = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int thread_count = std::min<int>(panel.threads > 0 ? panel.threads : hardware, static_cast<int>(units));
  std::vector<std::thread> threads;
  for (int t = 1; t < thread_count; ++t) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);
  std::vector<FailureEstimate> estimates;
  for (std::size_t p = 0; p < problems.size(); ++p) {
    estimates.push_back(estimateOf(tallies[p], panel.runs_per_eval, budgets[p]));
    for (std::size_t a = 0; a < agent_count; ++a) {
      for (const auto& [signature, runs] : signatures[p * agent_count + a]) estimates.back().signatures[signature] += runs;
    }
  }
  return estimates;
}

Fitness makeFailureFitness(const FailurePanel& panel) {
  checkPanel(panel.agents);
  panel.episode.validate();
  if (panel.runs_per_eval < 1 || panel.runs_per_eval > generator::kMaxRunsPerEval) {
    throw InvalidArgument("runs_per_eval", "expected runs in [1, " + std::to_string(generator::kMaxRunsPerEval) +
                                               "], got " + std::to_string(panel.runs_per_eval));
  }
  if (panel.round_size < 1 || panel.round_size > generator::kMaxRoundSize) {
    throw InvalidArgument("round_size", "expected matings per round in [1, " + std::to_string(generator::kMaxRoundSize) +
                                            "], got " + std::to_string(panel.round_size));
  }
  if (panel.threads < 0 || panel.threads > kMaxThreads) {
    throw InvalidArgument("threads", "expected 0 (every core) or a count up to " + std::to_string(kMaxThreads) +
                                         ", got " + std::to_string(panel.threads));
  }
  if (!isPanelFitness(panel.fitness)) {
    throw InvalidArgument("fitness", "'" + panel.fitness + "' is not a panel fitness (" + kFailureFitness + " or " +
                                         kRegretFitness + ")");
  }
  Fitness fitness;
  fitness.name = panel.fitness;
  fitness.maximise = true;
  fitness.batch_size = panel.round_size;
  fitness.batch = [panel](const std::vector<const Problem*>& problems, const std::vector<const Grid*>& grids) {
    std::vector<generator::FitnessScore> scores;
    for (const FailureEstimate& e : estimateFailures(panel, problems, grids)) scores.push_back(panelScore(panel.fitness, e));
    return scores;
  };
  return fitness;
}

Fitness fitnessFor(const GeneratorOptions& options, const std::vector<agents::AgentConfig>& available,
                   const EpisodeOptions& episode, int threads) {
  if (!isPanelFitness(options.fitness)) {
    return makeFitness(options.fitness, FitnessParameters{options.weights, options.seed});
  }
  FailurePanel panel;
  panel.fitness = options.fitness;
  panel.agents = resolvePanel(options.agents, available);
  panel.episode = episode;
  panel.episode.robot_radius = options.robot_radius;  // the robot its PPPs are solvable for
  panel.runs_per_eval = options.runs_per_eval;
  panel.round_size = options.round_size;
  panel.seed = options.seed;
  panel.threads = threads;
  panel.signatures = options.archive == kSignatureArchive;
  return makeFailureFitness(panel);
}

Fitness fitnessFor(const GeneratorOptions& options, const EpisodeOptions& episode, int threads) {
  const std::vector<agents::AgentConfig> available =
      options.agents_file.empty() ? std::vector<agents::AgentConfig>{} : agents::loadAgentConfigs(options.agents_file);
  return fitnessFor(options, available, episode, threads);
}

const std::vector<OptionSpec<EpisodeOptions>>& huntEpisodeOptionSpecs() {
  static const std::vector<OptionSpec<EpisodeOptions>> specs = [] {
    std::vector<OptionSpec<EpisodeOptions>> list = episodeOptionSpecs();
    list.erase(std::remove_if(list.begin(), list.end(), [](const auto& s) { return s.name == "robot_radius"; }),
               list.end());
    return list;
  }();
  return specs;
}

std::vector<agents::AgentConfig> resolvePanel(const std::vector<std::string>& names,
                                              const std::vector<agents::AgentConfig>& available,
                                              bool allow_planners) {
  if (names.empty()) throw InvalidArgument("agents", "empty panel: a panel fitness (failure, regret) needs at least one agent name");
  std::vector<agents::AgentConfig> panel;
  for (const std::string& name : names) {
    if (std::any_of(panel.begin(), panel.end(), [&](const agents::AgentConfig& a) { return a.name == name; })) {
      throw InvalidArgument("agents", "'" + name + "' named twice");
    }
    if (available.empty()) {
      const auto& types = agents::agentTypeNames();
      if (std::find(types.begin(), types.end(), name) == types.end()) {
        throw InvalidArgument("agents", "unknown agent '" + name + "'; with no agents file the names are built-in "
                                        "types: " + joinNames(types));
      }
      agents::AgentConfig config;
      config.name = name;
      config.type = name;
      panel.push_back(config);
      continue;
    }
    const auto found = std::find_if(available.begin(), available.end(),
                                    [&](const agents::AgentConfig& a) { return a.name == name; });
    if (found == available.end()) {
      std::vector<std::string> valid;
      for (const agents::AgentConfig& a : available) valid.push_back(a.name);
      throw InvalidArgument("agents", "unknown agent '" + name + "'; valid: " + joinNames(valid));
    }
    panel.push_back(*found);
  }
  if (allow_planners) {
    for (const agents::AgentConfig& a : panel) a.validate();
  } else {
    checkPanel(panel);
  }
  return panel;
}

}  // namespace generator
}  // namespace ppp
