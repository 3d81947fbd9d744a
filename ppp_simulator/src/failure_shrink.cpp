#include "ppp_simulator/failure_shrink.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "ppp_agents/episode_runner.hpp"
#include "ppp_agents/prepared_set.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {
namespace simulator {

namespace {

/// How many of the runs of `outcome` show `keep`.
int shownRuns(const RunsOutcome& outcome, const FailureToKeep& keep) {
  if (keep.kind.empty()) return outcome.failed;
  const int kind = outcome.kinds[static_cast<std::size_t>(diagnosis::kindIndex(keep.kind))];
  return keep.endless ? std::min(kind, outcome.endless) : kind;
}

/// "3 of 3": how many of the runs show `keep`.
std::string shownText(const RunsOutcome& outcome, const FailureToKeep& keep) {
  return std::to_string(shownRuns(outcome, keep)) + " of " + std::to_string(outcome.runs);
}

}  // namespace

std::string seedList(const std::vector<std::uint64_t>& seeds) {
  std::string text;
  for (const std::uint64_t s : seeds) text += (text.empty() ? "" : ",") + std::to_string(s);
  return text;
}

RunsOutcome outcomeOfRows(const std::vector<agents::EpisodeResult>& rows) {
  RunsOutcome outcome;
  for (const agents::EpisodeResult& row : rows) {
    ++outcome.runs;
    if (row.diagnosis.empty()) continue;
    ++outcome.failed;
    ++outcome.kinds[static_cast<std::size_t>(diagnosis::kindIndex(row.diagnosis))];
    if (row.endless_step >= 0) ++outcome.endless;
    ++outcome.signatures[row.signature];
  }
  return outcome;
}

bool solvableForRobot(const Problem& problem, const EpisodeOptions& episode) {
  try {
    agents::prepareSingle("shrink", "candidate", problem, episode);
    return true;
  } catch (const InvalidArgument&) {
    return false;
  }
}

RunsOutcome playRuns(const Problem& problem, const agents::AgentConfig& agent, const EpisodeOptions& episode,
                     const std::vector<std::uint64_t>& seeds) {
  std::optional<agents::PreparedSet> set;
  try {
    set.emplace(agents::prepareSingle("shrink", "candidate", problem, episode));
  } catch (const InvalidArgument&) {  // unsolvable for the robot
    return RunsOutcome{false};
  }
  agents::EpisodeRunner runner(agent, episode);
  const std::unique_ptr<agents::Agent> player = agents::makeAgent(agent);
  std::vector<agents::EpisodeResult> rows;
  for (const std::uint64_t seed : seeds) {
    const EpisodeOutcome o = runner.run(set->set.problems[0], set->grids[0], *player, seed, false, agents::windowsOf(*set, 0));
    rows.push_back(agents::episodeResult(*set, 0, agent.name, static_cast<int>(rows.size()), seed, o));
  }
  return outcomeOfRows(rows);
}

RunsPlayer playerOfRows(RowsPlayer rows, const EpisodeOptions& episode) {
  return [rows = std::move(rows), episode](const Problem& problem, const std::vector<std::uint64_t>& seeds) {
    if (!solvableForRobot(problem, episode)) return RunsOutcome{false};
    return outcomeOfRows(rows(problem, seeds));
  };
}

FailureToKeep failureShown(const RunsOutcome& outcome, bool any_kind) {
  FailureToKeep keep;
  if (any_kind) {
    keep.failures = outcome.failed;
    return keep;
  }
  const auto most = std::max_element(outcome.kinds.begin(), outcome.kinds.end());  // the first of equals
  keep.failures = *most;
  if (*most > 0) keep.kind = diagnosis::kKinds[most - outcome.kinds.begin()];
  keep.endless = keep.kind == diagnosis::kLoop && outcome.endless >= keep.failures;
  return keep;
}

std::string FailureToKeep::text() const {
  if (kind.empty()) return "any failure";
  return endless ? "endless " + kind : kind;
}

bool stillShows(const RunsOutcome& outcome, const FailureToKeep& keep) {
  if (!outcome.valid || keep.failures <= 0) return false;
  return shownRuns(outcome, keep) >= keep.failures;
}

void FailureJudging::validate() const {
  if (seeds.empty()) throw InvalidArgument("seeds", "expected at least one run seed to judge");
  if (!(min_rate >= 0 && min_rate <= 1)) {
    throw InvalidArgument("min_rate", "expected a share of runs in (0, 1], or 0 for the original's, got " +
                                          formatShortest(min_rate));
  }
}

RunsPlayer FailureJudging::player() const {
  if (play) return play;
  return [agent = agent, episode = episode](const Problem& p, const std::vector<std::uint64_t>& s) {
    return playRuns(p, agent, episode, s);
  };
}

std::uint64_t firstFailingSeed(const Problem& problem, const FailureJudging& judging) {
  const RunsPlayer play = judging.player();
  for (const std::uint64_t seed : judging.seeds) {
    if (play(problem, {seed}).failed > 0) return seed;
  }
  return judging.seeds.at(0);
}

ShrunkFailure shrinkFailure(const Problem& problem, const std::string& source, const FailureJudging& judging,
                            ShrinkUnits units, const StopCheck& stop) {
  judging.validate();
  const agents::AgentConfig& agent = judging.agent;
  const std::vector<std::uint64_t>& seeds = judging.seeds;
  const RunsPlayer play = judging.player();
  ShrunkFailure shrunk;
  shrunk.before = play(problem, seeds);
  if (!shrunk.before.valid) {
    throw InvalidArgument("problem", source + " cannot be solved by the robot (robot_radius): nothing to shrink");
  }
  shrunk.kept = failureShown(shrunk.before, judging.any_kind);
  if (shrunk.kept.failures == 0) {
    throw InvalidArgument("problem", agent.name + " passes " + source + " in all " + std::to_string(seeds.size()) +
                                         " runs judged: nothing to shrink");
  }
  if (judging.min_rate > 0) {
    const int needed = static_cast<int>(std::ceil(judging.min_rate * static_cast<double>(seeds.size()) - 1e-9));
    if (shrunk.kept.failures < needed) {
      throw InvalidArgument("problem", agent.name + " fails " + source + " " +
                                           (shrunk.kept.kind.empty() ? "" : "as " + shrunk.kept.text() + " ") +
                                           "in " + shownText(shrunk.before, shrunk.kept) +
                                           " runs, below the rate asked for: nothing to shrink");
    }
    shrunk.kept.failures = std::max(needed, 1);
  }
  const ShrinkResult result = shrinkProblem(
      problem, [&](const Problem& p) { return stillShows(play(p, seeds), shrunk.kept); }, units, stop);
  shrunk.problem = result.problem;
  shrunk.evaluations = result.evaluations;
  shrunk.after = play(shrunk.problem, seeds);
  shrunk.descriptors_before = static_cast<int>(problem.obstacles.size());
  shrunk.descriptors_after = static_cast<int>(shrunk.problem.obstacles.size());
  shrunk.cells_before = decodeGrid(problem).obstacleCount();
  shrunk.cells_after = decodeGrid(shrunk.problem).obstacleCount();
  Metadata& meta = shrunk.problem.metadata;
  // The original's measures (its fitness value, its characters) do not describe the shrunk PPP.
  meta.erase(std::remove_if(meta.begin(), meta.end(),
                            [](const auto& entry) {
                              return entry.first == "fitness_value" || entry.first.rfind("character.", 0) == 0;
                            }),
             meta.end());
  // Its fitness is now the failure fitness's measure: the share of the judged runs that still fail so.
  setMetadata(&meta, "fitness", "failure");
  setMetadata(&meta, "fitness_value",
              formatShortest(static_cast<double>(shownRuns(shrunk.after, shrunk.kept)) / std::max(1, shrunk.after.runs)));
  setMetadata(&meta, "shrunk_from", source);
  setMetadata(&meta, "shrink_agent", agent.name);
  setMetadata(&meta, "shrink_seeds", seedList(seeds));
  setMetadata(&meta, "shrink_kind", shrunk.kept.kind.empty() ? "any" : shrunk.kept.kind);
  setMetadata(&meta, "shrink_failed", shownText(shrunk.after, shrunk.kept));
  if (shrunk.kept.endless) setMetadata(&meta, "shrink_endless", "true");
  setMetadata(&meta, "descriptors_before", std::to_string(shrunk.descriptors_before));
  setMetadata(&meta, "descriptors_after", std::to_string(shrunk.descriptors_after));
  setMetadata(&meta, "obstacle_cells_before", std::to_string(shrunk.cells_before));
  setMetadata(&meta, "obstacle_cells_after", std::to_string(shrunk.cells_after));
  setMetadata(&meta, "shrink_evaluations", std::to_string(shrunk.evaluations));
  return shrunk;
}

}  // namespace simulator
}  // namespace ppp
