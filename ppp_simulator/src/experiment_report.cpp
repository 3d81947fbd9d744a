#include "ppp_simulator/experiment_report.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <numeric>
#include <optional>
#include <set>

#include "ppp_agents/agent_registry.hpp"
#include "ppp_agents/continuous/continuous_agent.hpp"
#include "ppp_agents/continuous/continuous_runner.hpp"
#include "ppp_core/csv.hpp"
#include "ppp_core/parallel_for.hpp"
#include "ppp_core/reachability.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_agents/episode_runner.hpp"
#include "ppp_simulator/failure_shrink.hpp"
#include "ppp_simulator/report/continuous_animation.hpp"
#include "ppp_simulator/report/episode_animation.hpp"
#include "ppp_simulator/report/pass_rates.hpp"

namespace ppp {
namespace simulator {

namespace {

/// True for a planner agent that plays in continuous motion: its runs are drawn from the commands it sent.
bool drivenPlanner(const agents::AgentConfig& agent, const EpisodeOptions& episode) {
  return agents::isPlanner(agent) && agents::playsContinuously(agent, episode);
}

/// A planner's run in continuous motion played again from its recorded `commands` (ended as `reason`): its
/// trajectory, and its animation when the map is small enough.
struct DrivenReplay {
  ContinuousOutcome outcome;
  std::string gif;
};

DrivenReplay replayDriven(const Problem& ppp, const Grid& grid, const agents::AgentConfig& agent,
                          const EpisodeOptions& episode, std::uint64_t seed,
                          const std::vector<BodyVelocity>& commands, const std::string& reason,
                          const AnimationOptions& animation, const StopCheck& stop) {
  if (std::max(ppp.width, ppp.height) <= kReportAnimationMaxSide) {
    ContinuousAnimation drawn =
        animateRecordedContinuousRun(ppp, grid, agent, episode, seed, commands, reason, animation, stop);
    return {std::move(drawn.outcome), std::move(drawn.gif)};
  }
  return {agents::recordedContinuousRun(ppp, grid, episode, fewestMoves(grid, ppp.start, ppp.goal, Connectivity::Four),
                                        seed, commands, reason, agent.name),
          ""};
}

/// The picture of a continuous run `outcome` under `episode`.
DrivenRun drivenRunOf(const ContinuousOutcome& outcome, const EpisodeOptions& episode) {
  return DrivenRun{outcome.poses, episode.motion.resolution, episode.robot_radius * episode.motion.resolution,
                   outcome.distance};
}

/// The run `row` of `agent` on PPP `problem` of `set`, replayed for its path and animated.
FailureExample replayedRun(const ExperimentConfig& config, const agents::PreparedSet& set, int problem,
                           const agents::AgentConfig& agent_config, const agents::EpisodeResult& row,
                           const StopCheck& stop) {
  stopIfAsked(stop);
  const Problem& ppp = set.set.problems[problem];
  AnimationOptions animation;
  animation.max_frames = config.animation_frames;
  FailureExample example;
  example.diagnosis = agents::diagnosisOf(row);
  if (drivenPlanner(agent_config, config.episode)) {  // drawn from its recorded commands (replayable())
    DrivenReplay run = replayDriven(ppp, set.grids[problem], agent_config, config.episode, row.seed, row.commands,
                                    row.reason, animation, stop);
    example.path = run.outcome.cells;
    example.reason = run.outcome.reason;
    example.driven = drivenRunOf(run.outcome, config.episode);
    example.animation_gif = std::move(run.gif);
  } else {
    EpisodeAnimation run;
    if (agents::isPlanner(agent_config)) {  // another process's run: drawn from its recorded actions (replayable())
      run = animateRecordedEpisode(ppp, set.grids[problem], agent_config, config.episode, row.seed, row.actions,
                                   row.reason, animation, stop);
    } else if (std::max(ppp.width, ppp.height) <= kReportAnimationMaxSide) {
      run = animateEpisode(ppp, set.grids[problem], agent_config, config.episode, row.seed, animation, stop);
    } else {
      run.outcome = agents::recordEpisode(ppp, set.grids[problem], agent_config, config.episode, row.seed);
    }
    example.path = run.outcome.path;
    example.reason = run.outcome.reason;
    example.cycle = cycleCells(example.diagnosis, run.outcome.cells);
    example.animation_gif = std::move(run.gif);
  }
  example.set = set.name;
  example.problem = set.set.ids[problem];
  example.agent = agent_config.name;
  example.run = row.run;
  example.seed = row.seed;
  example.ppp = ppp;
  example.recorded = agents::isPlanner(agent_config);
  example.replay_flags = agents::replayFlags(agent_config, config.episode);
  return example;
}

/// The PPP of the pictured run `run` of `agent` shrunk for that run's seed (shrinkFailure()), with the run on it:
/// a built-in agent's played in process, a planner's by `planner_rows` (and drawn from the actions of its row);
/// nothing when it does not fail there the way it is diagnosed (a soft failure, say).
std::optional<ShrunkExample> shrunkRun(const ExperimentConfig& config, const agents::AgentConfig& agent,
                                       const FailureExample& run, const PlannerRows& planner_rows,
                                       const StopCheck& stop) {
  const EpisodeOptions& episode = config.episode;
  const bool planner = agents::isPlanner(agent);
  const RowsPlayer rows = planner ? RowsPlayer([&](const Problem& p, const std::vector<std::uint64_t>& seeds) {
    return planner_rows(agent, p, seeds);
  })
                                  : RowsPlayer();
  FailureJudging judging;
  judging.agent = agent;
  judging.episode = episode;
  judging.seeds = {run.seed};
  if (planner) judging.play = playerOfRows(rows, episode);
  ShrunkFailure shrunk;
  try {
    shrunk = shrinkFailure(run.ppp, run.set + "/" + run.problem + ".ppp", judging, ShrinkUnits::Descriptors, stop);
  } catch (const InvalidArgument& e) {
    if (e.name() != "problem") throw;
    return std::nullopt;
  } catch (const AgentUnreachable&) {  // a planner gone since its runs: its worst PPP stays unshrunk
    return std::nullopt;
  }
  ShrunkExample example;
  const Grid grid = decodeGrid(shrunk.problem);
  EpisodeOutcome outcome;
  Diagnosis diagnosis;
  AnimationOptions animation;
  animation.max_frames = config.animation_frames;
  const bool animated = std::max(shrunk.problem.width, shrunk.problem.height) <= kReportAnimationMaxSide;
  if (drivenPlanner(agent, episode)) {  // its run again, through the simulator's lanes: drawn from its commands
    const std::vector<agents::EpisodeResult> played = rows(shrunk.problem, {run.seed});
    DrivenReplay replay = replayDriven(shrunk.problem, grid, agent, episode, run.seed, played.at(0).commands,
                                       played.at(0).reason, animation, stop);
    example.driven = drivenRunOf(replay.outcome, episode);
    if (animated) example.animation_gif = std::move(replay.gif);
    diagnosis = agents::diagnosisOf(played.at(0));
    outcome.path = replay.outcome.cells;
  } else if (planner) {  // its run again, through the simulator's lanes: drawn from its actions
    const std::vector<agents::EpisodeResult> played = rows(shrunk.problem, {run.seed});
    EpisodeAnimation recorded = animateRecordedEpisode(shrunk.problem, grid, agent, episode, run.seed,
                                                       played.at(0).actions, played.at(0).reason, animation, stop);
    outcome = std::move(recorded.outcome);
    if (animated) example.animation_gif = std::move(recorded.gif);
    diagnosis = agents::diagnosisOf(played.at(0));
  } else {
    if (animated) {
      EpisodeAnimation replayed = animateEpisode(shrunk.problem, grid, agent, episode, run.seed, animation, stop);
      outcome = std::move(replayed.outcome);
      example.animation_gif = std::move(replayed.gif);
    } else {
      outcome = agents::recordEpisode(shrunk.problem, grid, agent, episode, run.seed);
    }
    diagnosis = diagnoseRun(outcome.passed, false, outcome.reason, outcome.cells);
  }
  example.ppp = shrunk.problem;
  example.path = outcome.path;
  example.cycle = cycleCells(diagnosis, outcome.cells);
  example.summary = std::to_string(shrunk.descriptors_after) + " of " + std::to_string(shrunk.descriptors_before) +
                    " descriptors, " + std::to_string(shrunk.cells_after) + " of " + std::to_string(shrunk.cells_before) +
                    " obstacle cells, still " + shrunk.kept.text() + " in " +
                    *findMetadata(shrunk.problem.metadata, "shrink_failed") + " run";
  return example;
}

/// Whether the report shows runs of `agent`: not the control or the random baseline (nor a built-in agent in
/// continuous motion: only the control drives).
bool replayedInReport(const agents::AgentConfig& agent, const EpisodeOptions& episode) {
  if (agents::playsContinuously(agent, episode) && !agents::isPlanner(agent)) return false;
  const agents::AgentType& type = agents::agentType(agent.type);
  return !type.has(agents::AgentTrait::Control) && !type.has(agents::AgentTrait::Baseline);
}

/// Whether the run `row` of `agent` on `ppp` can be shown: any run of an agent played in process; a planner's
/// when its actions (planner_moves.csv) or, in continuous motion, its commands (kept in memory by this run of the
/// experiment) were recorded, and its map is small enough to animate.
bool replayable(const agents::AgentConfig& agent, const agents::EpisodeResult& row, const Problem& ppp) {
  const std::size_t recorded = row.commands.empty() ? row.actions.size() : row.commands.size();
  return !agents::isPlanner(agent) || (static_cast<int>(recorded) == row.steps &&
                                       std::max(ppp.width, ppp.height) <= kReportAnimationMaxSide);
}

/// `row` (of `agent` on `ppp`) with what draws it: a planner's run in continuous motion with its commands, played
/// again through `planner_rows` (a planner in lockstep plays a run the same way each time); nothing when it cannot be
/// played there or ends otherwise than `row` says.
std::optional<agents::EpisodeResult> withRecording(const agents::EpisodeResult& row, const agents::AgentConfig& agent,
                                                   const EpisodeOptions& episode, const Problem& ppp,
                                                   const PlannerRows& planner_rows) {
  if (!drivenPlanner(agent, episode) || !row.commands.empty()) return row;
  if (!planner_rows || std::max(ppp.width, ppp.height) > kReportAnimationMaxSide) return std::nullopt;
  std::vector<agents::EpisodeResult> played;
  try {
    played = planner_rows(agent, ppp, {row.seed});
  } catch (const AgentUnreachable&) {
    return std::nullopt;
  }
  if (played.size() != 1 || played[0].steps != row.steps || played[0].reason != row.reason) return std::nullopt;
  agents::EpisodeResult recorded = row;
  recorded.commands = std::move(played[0].commands);
  return recorded;
}

/// The first failing run of `agent` on PPP `problem` of `set`, replayed for its path and animated; nothing when
/// it cannot be (replayable(), withRecording()).
std::optional<FailureExample> failingRun(const ExperimentConfig& config, const agents::PreparedSet& set, int problem,
                          const agents::AgentConfig& agent_config, const std::vector<ResultGroup>& groups,
                          const StopCheck& stop, const PlannerRows& planner_rows) {
  const agents::EpisodeResult* first_fail = nullptr;
  for (const ResultGroup& g : groups) {
    const agents::EpisodeResult* f = g.first_fail;
    if (f != nullptr && f->agent == agent_config.name && f->problem == set.set.ids[problem] && f->set == set.name &&
        (first_fail == nullptr || f->run < first_fail->run)) {
      first_fail = f;
    }
  }
  const std::optional<agents::EpisodeResult> row =
      withRecording(*first_fail, agent_config, config.episode, set.set.problems[problem], planner_rows);
  if (!row || !replayable(agent_config, *row, set.set.problems[problem])) return std::nullopt;
  return replayedRun(config, set, problem, agent_config, *row, stop);
}

}  // namespace

std::vector<AgentFailureKinds> failureKinds(const ExperimentConfig& config, const std::vector<agents::PreparedSet>& sets,
                                            const std::vector<agents::EpisodeResult>& rows) {
  std::map<std::pair<std::string, std::string>, std::pair<int, int>> where;  // (set, id) -> (set, problem)
  for (int s = 0; s < static_cast<int>(sets.size()); ++s) {
    for (int p = 0; p < static_cast<int>(sets[s].set.ids.size()); ++p) where[{sets[s].name, sets[s].set.ids[p]}] = {s, p};
  }
  std::map<std::string, FailureGrouping> by_agent;  // the agents the report shows (not the control or the baseline)
  for (const agents::AgentConfig& agent : config.agents) {
    if (replayedInReport(agent, config.episode)) by_agent[agent.name];
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const agents::EpisodeResult& row = rows[i];
    const auto grouping = by_agent.find(row.agent);
    if (row.signature.empty() || grouping == by_agent.end()) continue;
    const auto found = where.find({row.set, row.problem});
    if (found == where.end()) continue;
    const auto [s, p] = found->second;
    grouping->second.add(row.signature, row.set + "/" + row.problem,
                            sets[s].grids[static_cast<std::size_t>(p)].obstacleCount(), i);
  }
  std::vector<AgentFailureKinds> kinds;
  for (const agents::AgentConfig& agent : config.agents) {
    const auto grouped = by_agent.find(agent.name);
    if (grouped == by_agent.end() || grouped->second.total() == 0) continue;
    const std::vector<DistinctFailure> groups = grouped->second.groups();
    AgentFailureKinds a{agent.name, static_cast<int>(groups.size()), grouped->second.total(), {}};
    for (std::size_t k = 0; k < groups.size() && k < static_cast<std::size_t>(kShownFailureKinds); ++k) {
      const agents::EpisodeResult& row = rows[groups[k].smallest];
      const auto [s, p] = where.at({row.set, row.problem});
      a.shown.push_back(FailureKind{groups[k], agents::diagnosisOf(row).kind, row.set, row.problem,
                                    sets[s].set.problems[static_cast<std::size_t>(p)], row.seed,
                                    agents::isPlanner(agent) ? "" : agents::replayFlags(agent, config.episode)});
    }
    kinds.push_back(std::move(a));
  }
  return kinds;
}

std::vector<FailureExample> hardestFailures(const ExperimentConfig& config, const std::vector<agents::PreparedSet>& sets,
                                            const std::vector<ResultGroup>& groups, int count,
                                            const StopCheck& stop) {
  std::map<std::string, const agents::AgentConfig*> agent_by_name;
  for (const auto& a : config.agents) agent_by_name[a.name] = &a;
  // Pass counts per (set, problem, agent), over the agents that are not the control.
  std::map<std::tuple<std::string, std::string, std::string>, std::pair<int, int>> counts;
  for (const ResultGroup& g : groups) {
    // The control always passes; a planner's path cannot be replayed in-process for the picture.
    const agents::EpisodeResult& r = *g.row;
    const agents::AgentConfig& agent = *agent_by_name.at(r.agent);
    if (agents::agentType(agent.type).has(agents::AgentTrait::Control) || agents::isPlanner(agent)) continue;
    auto& c = counts[{r.set, r.problem, r.agent}];
    c.first += g.passes;
    c.second += g.runs;
  }
  // Each agent's mean pass rate over every PPP, so the failure shown for a PPP is the agent it hurts most
  // relative to that agent's usual performance (the random baseline fails everywhere and would say little).
  std::map<std::string, std::pair<double, int>> agent_means;
  for (const auto& entry : counts) {
    auto& mean = agent_means[std::get<2>(entry.first)];
    mean.first += static_cast<double>(entry.second.first) / entry.second.second;
    ++mean.second;
  }
  struct Candidate {
    double mean_rate;
    int set;
    int problem;
    std::string worst_agent;
  };
  std::vector<Candidate> candidates;
  for (int s = 0; s < static_cast<int>(sets.size()); ++s) {
    for (int p = 0; p < static_cast<int>(sets[s].set.ids.size()); ++p) {
      double total = 0;
      int agents = 0;
      double largest_drop = -2.0;
      std::string worst_agent;
      for (const auto& a : config.agents) {
        const auto it = counts.find({sets[s].name, sets[s].set.ids[p], a.name});
        if (it == counts.end() || it->second.second == 0) continue;
        const double rate = static_cast<double>(it->second.first) / it->second.second;
        total += rate;
        ++agents;
        const auto& mean = agent_means[a.name];
        const double drop = mean.first / mean.second - rate;
        if (rate < 1.0 && drop > largest_drop) largest_drop = drop, worst_agent = a.name;
      }
      if (agents > 0 && !worst_agent.empty()) candidates.push_back({total / agents, s, p, worst_agent});
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.mean_rate < b.mean_rate; });
  if (static_cast<int>(candidates.size()) > count) candidates.resize(static_cast<std::size_t>(count));
  std::vector<FailureExample> failures;
  for (const Candidate& c : candidates) {
    // Planners are not candidates, so every run here can be replayed.
    failures.push_back(
        *failingRun(config, sets[c.set], c.problem, *agent_by_name.at(c.worst_agent), groups, stop, {}));
  }
  return failures;
}

std::vector<FailureExample> worstFailures(const ExperimentConfig& config, const std::vector<agents::PreparedSet>& sets,
                                          const std::vector<ResultGroup>& groups, const StopCheck& stop,
                                          const PlannerRows& planner_rows) {
  std::map<std::string, int> set_index;
  std::vector<std::map<std::string, int>> problem_index(sets.size());
  for (int s = 0; s < static_cast<int>(sets.size()); ++s) {
    set_index[sets[s].name] = s;
    for (int p = 0; p < static_cast<int>(sets[s].set.ids.size()); ++p) problem_index[s][sets[s].set.ids[p]] = p;
  }
  // (agent, set, problem) -> (passes, runs), in one pass over the groups.
  std::map<std::string, std::map<std::pair<int, int>, std::pair<int, int>>> counts;
  for (const ResultGroup& g : groups) {
    const agents::EpisodeResult& r = *g.row;
    const int s = set_index.at(r.set);
    auto& c = counts[r.agent][{s, problem_index[s].at(r.problem)}];
    c.first += g.passes;
    c.second += g.runs;
  }
  std::vector<std::pair<const agents::AgentConfig*, std::pair<int, int>>> picked;  // agent, (set, problem)
  for (const agents::AgentConfig& agent : config.agents) {
    if (!replayedInReport(agent, config.episode)) continue;
    double lowest = 1.0;
    std::pair<int, int> at{-1, -1};
    for (const auto& [where, c] : counts[agent.name]) {  // set order, then PPP order: the first of equals wins
      const double rate = static_cast<double>(c.first) / c.second;
      if (rate < lowest) lowest = rate, at = where;
    }
    if (at.first >= 0) picked.emplace_back(&agent, at);
  }
  // Each agent's run replayed and shrunk on a thread of its own (the experiment's threads; a planner's played through
  // planner_rows), kept in agent order. The costliest start first, so that no thread is left alone with one at the
  // end: planners driven in continuous motion, then other planners (their runs go through ROS), then the rest.
  const auto cost = [&](std::size_t i) {
    const agents::AgentConfig& agent = *picked[i].first;
    return drivenPlanner(agent, config.episode) ? 2 : agents::isPlanner(agent) ? 1 : 0;
  };
  std::vector<std::size_t> order(picked.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost(a) > cost(b); });
  std::vector<std::optional<FailureExample>> runs(picked.size());
  parallelFor(order.size(), config.threads, [&](std::size_t k) {
    const std::size_t i = order[k];
    const agents::AgentConfig& agent = *picked[i].first;
    const auto [set, problem] = picked[i].second;
    runs[i] = failingRun(config, sets[set], problem, agent, groups, stop, planner_rows);
    // A run lost to the agent link, or to its planner's end, cannot be judged again: there is nothing to shrink.
    if (runs[i] && config.shrink_worst && (!runs[i]->recorded || planner_rows) &&
        !leavesAgentUnreachable(runs[i]->reason)) {
      runs[i]->shrunk = shrunkRun(config, agent, *runs[i], planner_rows, stop);
    }
  });
  std::vector<FailureExample> worst;
  for (std::optional<FailureExample>& run : runs) {
    if (run) worst.push_back(std::move(*run));
  }
  return worst;
}

std::vector<FailureExample> longestDetours(const ExperimentConfig& config, const std::vector<agents::PreparedSet>& sets,
                                           const std::vector<DetourStats>& detours, const StopCheck& stop,
                                           const PlannerRows& planner_rows) {
  std::vector<FailureExample> examples;
  for (const agents::AgentConfig& agent : config.agents) {
    if (!replayedInReport(agent, config.episode)) continue;
    const DetourStats* worst = nullptr;
    for (const DetourStats& d : detours) {
      if (d.agent == agent.name && (worst == nullptr || d.worst_mean > worst->worst_mean)) worst = &d;
    }
    if (worst == nullptr) continue;
    for (const agents::PreparedSet& set : sets) {
      if (set.name != worst->set) continue;
      const auto id = std::find(set.set.ids.begin(), set.set.ids.end(), worst->worst_problem);
      const int problem = static_cast<int>(id - set.set.ids.begin());
      const std::optional<agents::EpisodeResult> row =
          withRecording(*worst->longest, agent, config.episode, set.set.problems[problem], planner_rows);
      if (!row || !replayable(agent, *row, set.set.problems[problem])) continue;
      examples.push_back(replayedRun(config, set, problem, agent, *row, stop));
    }
  }
  return examples;
}

void writeExperimentReport(const std::string& dir, const ExperimentConfig& config, const std::string& config_text,
                           const std::vector<agents::PreparedSet>& sets, const std::vector<agents::EpisodeResult>& rows,
                           const StopCheck& stop, const PlannerRows& planner_rows) {
  std::vector<std::string> set_names, agent_names;
  for (const agents::PreparedSet& s : sets) set_names.push_back(s.name);
  // Agents with no rows (planners in an in-process run) are left out of the tables.
  const std::vector<ResultGroup> groups = groupResults(rows);
  std::set<std::string> agents_run;
  for (const ResultGroup& g : groups) agents_run.insert(g.row->agent);
  std::string other_runs;
  for (const auto& a : config.agents) {
    if (agents_run.count(a.name) == 0) continue;
    agent_names.push_back(a.name);
    if (config.runsFor(a) != config.runs) {
      other_runs += (other_runs.empty() ? "" : ", ") + a.name + " " + std::to_string(config.runsFor(a));
    }
  }
  ReportInput input;
  input.title = "PPP Lab experiment: " + std::to_string(sets.size()) + " sets, " +
                std::to_string(agent_names.size()) + " agents, " + std::to_string(config.runs) + " runs each" +
                (other_runs.empty() ? "" : " (" + other_runs + ")");
  input.config_text = config_text;
  for (const auto& a : config.agents) {
    if (agents::agentType(a.type).has(agents::AgentTrait::Control) && agents_run.count(a.name) > 0 && input.control.empty()) {
      input.control = a.name;
    }
  }
  input.rates = computeGroupedPassRates(groups, set_names, agent_names);
  input.references = compareWithReference(input.rates, config.reference);
  input.motion_pairs = motionPairs(config.agents, config.episode);
  for (std::size_t a = 0; a < sets.size(); ++a) {
    for (std::size_t b = a + 1; b < sets.size(); ++b) input.comparisons.emplace_back(sets[a].name, sets[b].name);
  }
  stopIfAsked(stop);
  input.failures = hardestFailures(config, sets, groups, config.hardest, stop);
  stopIfAsked(stop);
  input.worst = worstFailures(config, sets, groups, stop, planner_rows);
  input.failure_kinds = failureKinds(config, sets, rows);
  stopIfAsked(stop);
  input.detours = detourStats(rows, set_names, agent_names);
  input.detour_examples = longestDetours(config, sets, input.detours, stop, planner_rows);
  stopIfAsked(stop);
  for (const agents::PreparedSet& set : sets) {
    SetInfo info{set.name, set.set.diversity, ""};
    const std::filesystem::path archive = std::filesystem::path(set.directory) / "archive.svg";
    if (!set.directory.empty() && std::filesystem::exists(archive)) {
      info.archive_svg = readTextFile(archive.string(), 16u << 20);
    }
    input.sets.push_back(std::move(info));
  }
  std::filesystem::create_directories(dir);
  writeSummaryCsv((std::filesystem::path(dir) / "summary.csv").string(), input.rates);
  writeReport(dir, input, stop);
}

}  // namespace simulator
}  // namespace ppp
