#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_agents/agent_lane.hpp"
#include "ppp_agents/continuous/continuous_lane.hpp"
#include "ppp_agents/episode_result.hpp"
#include "ppp_agents/prepared_set.hpp"
#include "ppp_generator/failure_fitness.hpp"

namespace ppp {
namespace generator {

/// The reason PanelEvaluation::reasons gives a soft failure (a passed run; results.csv says goal_reached).
constexpr const char* kSoftFailureReason = "soft_failure";

/// What a panel's runs on one PPP of a hunt came to, with why runs failed.
struct PanelEvaluation {
  FailureEstimate estimate;             ///< Failure rate, budget used, regret, signatures, steps: as in process.
  int episodes = 0;                     ///< Runs played.
  int failed = 0;                       ///< Of them, failed.
  std::map<std::string, int> reasons;   ///< Failed runs per reason (budget_exhausted, soft_failure, ...).
  std::map<std::string, int> diagnoses; ///< Failed and soft-failed runs per diagnosis (loop, detour, ...).
  int endless = 0;                      ///< Of the loops, those proven endless (EpisodeResult::endless_step).
};

/// One evaluation request of a hunt, played through agent lanes (the simulator node's ~evaluate): per panel agent
/// one lane per instance (agents::instanceCount, each its share) of `runs` runs on every candidate, seeded by
/// failureRunSeed() exactly as the in-process failure fitness, so built-in agents give the same estimates through
/// ROS as in process; or, given `run_seeds`, run r seeded run_seeds[r] on every candidate (a shrink judging a
/// failure on its own seeds). A panel agent in continuous motion gets continuous lanes; its runs count in the
/// estimates as fractions of their own budgets of control periods (scaled to the grid's move budget), so its
/// budget used and regret are those of simulated time. Lanes may be played on separate threads; record() is
/// thread-safe.
class HuntEvaluation {
 public:
  /// Prepares the candidates (each must be solvable) and the lanes of every panel agent.
  /// @throws InvalidArgument naming "problems" (an unsolvable or invalid PPP), "runs", "run_seeds" (not `runs`
  /// of them) or the lane's options.
  HuntEvaluation(const std::vector<Problem>& problems, const std::vector<agents::AgentConfig>& panel,
                 const EpisodeOptions& episode, int runs, std::uint64_t generator_seed, int batch_size,
                 const std::vector<std::uint64_t>& run_seeds = {});
  /// The grid lanes in panel order, agents::instanceCount(agent) consecutive ones per panel agent on the grid.
  std::vector<std::unique_ptr<agents::AgentLane>>& lanes() { return lanes_; }
  /// The continuous lanes in panel order, agents::instanceCount(agent) consecutive ones per panel agent in
  /// continuous motion.
  std::vector<std::unique_ptr<agents::ContinuousLane>>& continuousLanes() { return continuous_lanes_; }
  /// True when every lane has played all its runs.
  bool finished() const;
  /// Takes finished episodes of any lane.
  void record(const std::vector<agents::EpisodeResult>& ended);
  /// Per candidate, in request order: what the recorded runs came to.
  std::vector<PanelEvaluation> evaluations() const;
  /// The recorded runs, in the order they ended (their `problem` is the candidate's id, "c0", "c1", ...). Kept only
  /// when the evaluation was given `run_seeds` (a shrink replaying its runs); a hunt's estimates need none of them.
  std::vector<agents::EpisodeResult> rows() const;

 private:
  int runs_;
  bool keeps_rows_;
  std::vector<agents::PreparedSet> sets_;  // one set of the candidates; the lanes refer to it
  std::vector<std::unique_ptr<agents::AgentLane>> lanes_;
  std::vector<std::unique_ptr<agents::ContinuousLane>> continuous_lanes_;
  MotionOptions motion_;               // the continuous lanes' budgets
  std::vector<bool> continuous_;       // per panel agent
  mutable std::mutex mutex_;
  std::vector<PanelTally> tallies_;
  std::vector<PanelEvaluation> evaluations_;
  std::vector<agents::EpisodeResult> rows_;
  std::map<std::string, int> agent_index_;
};

}  // namespace generator
}  // namespace ppp
