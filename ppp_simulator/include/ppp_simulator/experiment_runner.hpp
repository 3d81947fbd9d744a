#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/window_atlas.hpp"
#include "ppp_agents/agent_lane.hpp"
#include "ppp_agents/continuous/continuous_lane.hpp"
#include "ppp_agents/prepared_set.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_core/stop.hpp"
#include "ppp_agents/episode_runner.hpp"
#include "ppp_agents/episode_result.hpp"
#include "ppp_simulator/experiment_config.hpp"
#include "ppp_simulator/results_file.hpp"

namespace ppp {
namespace simulator {

/// The seed of one run, derived from the experiment seed and the run's names (not positions), so adding
/// an agent or a set leaves every other run's seed unchanged.
std::uint64_t runSeed(std::uint64_t experiment_seed, const std::string& set, const std::string& problem,
                      const std::string& agent, int run);

/// The lane of every run of `config` on every PPP of `sets` not in `done` (of them, `share`'s), seeded by
/// runSeed() with `experiment_seed`. @throws InvalidArgument.
agents::AgentLane experimentLane(const agents::AgentConfig& config, const EpisodeOptions& options,
                                 const std::vector<agents::PreparedSet>& sets, std::uint64_t experiment_seed, int runs,
                                 const std::set<RunKey>& done, int batch_size,
                                 agents::LaneShare share = {});

/// experimentLane()'s counterpart for an agent that plays in continuous motion.
agents::ContinuousLane experimentContinuousLane(const agents::AgentConfig& config, const EpisodeOptions& options,
                                                const std::vector<agents::PreparedSet>& sets,
                                                std::uint64_t experiment_seed, int runs, const std::set<RunKey>& done,
                                                int batch_size, agents::LaneShare share = {});

/// @throws InvalidArgument naming robot_radius when an agent of `config` plays in continuous motion and its disc
/// cannot stand at the start of a PPP of `sets`.
void checkContinuousStarts(const ExperimentConfig& config, const std::vector<agents::PreparedSet>& sets);

/// Generates (or reads) every set of the experiment into `dir`/sets/<name>/, reusing sets already there; a set
/// being generated when `stop` says stop is not written. @throws IoError, ParseError, InvalidArgument, Interrupted.
std::vector<agents::PreparedSet> prepareSets(const ExperimentConfig& config, const std::string& dir,
                                     const std::function<void(const std::string&)>& log = {},
                                     const StopCheck& stop = {});

/// Validates the experiment, checks `dir` and records the experiment's fingerprint in it.
/// @throws IoError, InvalidArgument.
void openExperimentDirectory(const ExperimentConfig& config, const std::string& dir);

/// openExperimentDirectory(), then prepareSets() (the first half of an
/// experiment, shared by runExperiment() and the ROS simulator node).
/// @throws IoError, ParseError, InvalidArgument, Interrupted.
std::vector<agents::PreparedSet> beginExperiment(const ExperimentConfig& config, const std::string& dir,
                                         const std::function<void(const std::string&)>& log = {},
                                         const StopCheck& stop = {});

/// The path of an experiment directory's results.csv.
std::string resultsPath(const std::string& dir);

/// Plays a planner agent of the experiment on one PPP once per seed, giving the rows as results.csv has them (the
/// simulator node's lanes), so the report can shrink planners' failures too; empty where planners cannot play
/// (`ppp experiment`). Throws AgentUnreachable when the planner is gone (a run lost to its link). Called from several
/// threads at once, for different agents (the report's worst PPPs are shrunk side by side).
using PlannerRows = std::function<std::vector<agents::EpisodeResult>(
    const agents::AgentConfig& agent, const Problem& problem, const std::vector<std::uint64_t>& seeds)>;

/// What a PlannerRows throws when the agent's link is lost: the report then leaves that agent's PPP unshrunk.
class AgentUnreachable : public IoError {
 public:
  using IoError::IoError;
};

/// Puts every row of results.csv in canonical order and writes summary.csv and the report (the second half);
/// `stop` is asked while reading and between the steps, each of which replaces its files whole; `log` hears
/// each step begin. @throws IoError, ParseError, Interrupted.
void finishExperiment(const ExperimentConfig& config, const std::string& config_text, const std::string& dir,
                      const std::vector<agents::PreparedSet>& sets, ResultsFile* results, const StopCheck& stop = {},
                      const std::function<void(const std::string&)>& log = {}, const PlannerRows& planner_rows = {});

/// What runExperiment() did.
struct ExperimentReport {
  long episodes_run = 0;      ///< Episodes simulated by this call.
  long episodes_resumed = 0;  ///< Episodes found already done in results.csv.
  bool interrupted = false;   ///< Stopped early on request; rerun to resume.
};

/// Runs an experiment into `dir`: experiment.yaml (the fingerprint), sets/, results.csv (rows streamed as
/// runs finish), then summary.csv and report.{md,html}. Rerunning on the same directory resumes: finished runs
/// are skipped and nothing is lost. A directory holding a different experiment is refused.
/// `progress` is called with (episodes done, total); `stop` saying stop ends every phase (generation between
/// rounds, episodes after the workers' current batch, the report between its steps) and returns with
/// interrupted = true. @throws IoError, ParseError, InvalidArgument.
ExperimentReport runExperiment(const ExperimentConfig& config, const std::string& config_text, const std::string& dir,
                               const std::function<void(long, long)>& progress = {},
                               const StopCheck& stop = {},
                               const std::function<void(const std::string&)>& log = {});

/// Checks before any work that `dir` is new, empty, or holds this same experiment.
/// @throws IoError naming the directory and what it holds.
void checkExperimentDirectory(const ExperimentConfig& config, const std::string& dir);

}  // namespace simulator
}  // namespace ppp
