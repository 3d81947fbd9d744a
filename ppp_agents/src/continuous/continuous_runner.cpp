#include "ppp_agents/continuous/continuous_runner.hpp"

#include <string>

#include "ppp_core/diagnosis.hpp"
#include "ppp_core/episode.hpp"
#include "ppp_core/episode_reason.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/optimum.hpp"
#include "ppp_core/reachability.hpp"
#include "ppp_core/square_world.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {
namespace agents {

void checkContinuousStart(const PreparedSet& set, int problem, const EpisodeOptions& options) {
  const SquareWorld world(set.grids[problem], options.motion.resolution);
  const Cell start = set.set.problems[problem].start;
  if (world.collides(world.frame().centreX(start), world.frame().centreY(start),
                     options.robot_radius * options.motion.resolution)) {
    throw InvalidArgument("robot_radius", "set '" + set.name + "', PPP " + set.set.ids[problem] + ": a disc of " +
                                              formatShortest(options.robot_radius) +
                                              " cells touches an obstacle or the border at the start in continuous "
                                              "motion; expected a robot that can stand there");
  }
}

int continuousOptimalMoves(const Problem& problem, const Grid& grid, const EpisodeOptions& options, int grid_moves) {
  const SquareWorld world(grid, options.motion.resolution);
  const Grid space = continuousConfigurationSpace(world, options.robot_radius * options.motion.resolution);
  const int moves = space.isFree(problem.start) && space.isFree(problem.goal)
                        ? fewestMoves(space, problem.start, problem.goal, Connectivity::Four)
                        : -1;
  return moves > 0 ? moves : grid_moves;
}

ContinuousEpisode continuousEpisode(const Problem& problem, const Grid& grid, const EpisodeOptions& options,
                                    int optimal, std::uint64_t run_seed, bool record_poses) {
  return ContinuousEpisode(problem, grid, options.motion, options.robot_radius,
                           continuousStepBudget(options.motion, optimal), run_seed, record_poses);
}

double longestContinuousRun(const std::vector<PreparedSet>& sets, const EpisodeOptions& options) {
  long periods = 0;
  for (const PreparedSet& set : sets) {
    for (std::size_t p = 0; p < set.set.problems.size(); ++p) {
      const int optimal = continuousOptimalMoves(set.set.problems[p], set.grids[p], options, set.moves[p]);
      periods = std::max(periods, continuousStepBudget(options.motion, optimal));
    }
  }
  return static_cast<double>(periods) * options.motion.control_period;
}

ContinuousStart continuousStart(const ContinuousEpisode& episode, const EpisodeOptions& options,
                                const AgentConfig& config, const Grid& grid, std::uint64_t run_seed) {
  ContinuousStart start;
  start.frame = episode.world().frame();
  start.pose = episode.pose();
  start.goal = episode.goal();
  start.radius = episode.radius();
  start.limits = episode.limits();
  start.beams = episode.beams();
  start.control_period = options.motion.control_period;
  start.seed = agentSeed(run_seed);
  start.prior_map = givenPriorMap(config) ? &grid : nullptr;
  return start;
}

EpisodeResult continuousResult(const PreparedSet& set, int problem, const std::string& agent, int run,
                               std::uint64_t seed, int optimal, const ContinuousOutcome& outcome,
                               const EpisodeOptions& options) {
  EpisodeResult r;
  r.set = set.name;
  r.problem = set.set.ids[problem];
  r.agent = agent;
  r.run = run;
  r.seed = seed;
  r.passed = outcome.passed;
  r.steps = outcome.steps;
  r.path_length = outcome.distance / options.motion.resolution;
  r.optimal_length = optimal;
  r.soft_failure = isSoftFailure(r.passed, r.path_length, r.optimal_length, options.soft_failure_ratio);
  r.reason = outcome.reason;
  setDiagnosisAndSignature(set, problem, diagnoseContinuousRun(r.passed, r.soft_failure, r.reason, outcome.cells),
                           outcome.cells, &r);
  return r;
}

ContinuousOutcome recordedContinuousRun(const Problem& problem, const Grid& grid, const EpisodeOptions& options,
                                        int grid_moves, std::uint64_t run_seed,
                                        const std::vector<BodyVelocity>& commands, const std::string& end_reason,
                                        const std::string& agent) {
  ContinuousEpisode episode = continuousEpisode(
      problem, grid, options, continuousOptimalMoves(problem, grid, options, grid_moves), run_seed, true);
  for (const BodyVelocity& command : commands) {
    if (episode.done()) break;
    episode.apply(command);
  }
  // Only the world ends a run on the goal, in a collision or at its budget; any other end came from the agent or
  // its link after the last command.
  const bool world_ends = end_reason == reason::kGoalReached || end_reason == reason::kCollision ||
                          end_reason == reason::kBudgetExhausted;
  const char* named = reason::reasonNamed(end_reason);
  if (!episode.done() && !world_ends && named != nullptr) episode.fail(named);
  const ContinuousOutcome& outcome = episode.outcome();
  if (!episode.done() || outcome.steps != static_cast<int>(commands.size()) || outcome.reason != end_reason) {
    throw Error("the recorded run of " + agent + " with seed " + std::to_string(run_seed) + " (" +
                std::to_string(commands.size()) + " commands, " + end_reason + ") plays again as " +
                std::to_string(outcome.steps) + " control periods, " +
                (episode.done() ? std::string("ending ") + outcome.reason : std::string("not ended")));
  }
  return outcome;
}

ContinuousRunner::ContinuousRunner(const AgentConfig& config, const EpisodeOptions& options)
    : config_(config), options_(options), agent_(makeContinuousAgent(config)) {}

ContinuousOutcome ContinuousRunner::run(const Problem& problem, const Grid& grid, int grid_moves,
                                        std::uint64_t run_seed, bool record_poses) {
  return play(problem, grid, continuousOptimalMoves(problem, grid, options_, grid_moves), run_seed, record_poses);
}

ContinuousOutcome ContinuousRunner::play(const Problem& problem, const Grid& grid, int optimal,
                                         std::uint64_t run_seed, bool record_poses) {
  ContinuousEpisode episode = continuousEpisode(problem, grid, options_, optimal, run_seed, record_poses);
  agent_->start(continuousStart(episode, options_, config_, grid, run_seed));
  const bool reads_laser = agent_->readsLaser();
  ranges_.clear();
  while (!episode.done()) {
    if (reads_laser) episode.scan(&ranges_);
    const ContinuousSensing sensing{episode.pose(), episode.velocity(), episode.time(), &ranges_};
    episode.apply(agent_->command(sensing));
  }
  return episode.outcome();
}

EpisodeResult ContinuousRunner::row(const PreparedSet& set, int problem, int run_number, std::uint64_t run_seed) {
  const Problem& ppp = set.set.problems[problem];
  const int optimal = continuousOptimalMoves(ppp, set.grids[problem], options_, set.moves[problem]);
  return continuousResult(set, problem, config_.name, run_number, run_seed, optimal,
                          play(ppp, set.grids[problem], optimal, run_seed, false), options_);
}

}  // namespace agents
}  // namespace ppp
