#pragma once

#include <cstdint>
#include <vector>

#include "ppp_core/action.hpp"
#include "ppp_core/connectivity.hpp"
#include "ppp_core/episode_reason.hpp"
#include "ppp_core/episode_options.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/sensor.hpp"
#include "ppp_core/window_atlas.hpp"

namespace ppp {

/// How one episode went.
struct EpisodeOutcome {
  bool passed = false;      ///< The agent stood on the goal within the budget.
  int steps = 0;            ///< Actions taken (counted against the budget or not).
  int bumps = 0;            ///< Actions that hit an obstacle or the edge.
  int path_length = 0;      ///< Cells actually moved.
  int diagonal_moves = 0;   ///< Of them, diagonal moves (connectivity 8).
  const char* reason = "";  ///< reason::kGoalReached, kBudgetExhausted or kActionLimit (or a failure's).
  std::vector<Cell> path;   ///< Cells visited, start first (only when asked for).
  /// The robot's cell after each action, start first: steps + 1 cells, bumps and stays included (always kept,
  /// complete once the episode is done: the diagnosis of a failed run reads it).
  std::vector<Cell> cells;
};

/// The length an episode moved: 1 per straight move, sqrt(2) per diagonal one.
double pathLength(const EpisodeOutcome& outcome);

/// The seed of the agent's own choices in a run with `run_seed`.
std::uint64_t agentSeed(std::uint64_t run_seed);
/// The seed of the sensor noise in a run with `run_seed`.
std::uint64_t noiseSeed(std::uint64_t run_seed);

/// One episode advanced a step at a time: the move model (4- or 8-connected; a move into an obstacle or off the
/// map, or a diagonal past an obstacle, leaves the agent in place and the next scan reports a bump; a diagonal
/// action under connectivity 4 fails the episode as an invalid action), the scans and the budget. The in-process
/// runner and the ROS simulator node both drive episodes through this class.
class Episode {
 public:
  /// Starts at the problem's start. `grid`, `sensor`, `windows` (the grid's atlas at the sensor's range, when
  /// there is one: scans become lookups) and `motion` (the robot's configuration space when it has a body:
  /// configurationSpace(); moves are checked against it, scans against `grid`) must outlive the episode.
  Episode(const Problem& problem, const Grid& grid, const SensorModel& sensor, std::uint64_t run_seed,
          BudgetRule budget, Connectivity connectivity, bool record_path = false, const WindowAtlas* windows = nullptr,
          const Grid* motion = nullptr);
  /// True once the agent stood on the goal, the budget was spent or fail() was called.
  bool done() const { return done_; }
  /// What the agent senses now (computed on first read).
  Scan scan() const;
  /// Applies the agent's action for this step.
  void apply(Action action);
  /// Ends the episode as failed for `reason` (e.g. reason::kTimeout).
  void fail(const char* reason);
  /// The outcome so far (final once done()).
  const EpisodeOutcome& outcome() const { return outcome_; }
  /// The outcome, moved out (the episode is done with it).
  EpisodeOutcome takeOutcome() { return std::move(outcome_); }
  /// Steps taken so far.
  int step() const { return outcome_.steps; }
  /// Asks the processor to fetch, for writing, where the next apply() records its cell: a caller stepping many
  /// episodes in turn calls it a few episodes ahead, since each one's trajectory has left the cache since its
  /// last step.
  void prefetchNextStep() const {
    if (!done_) __builtin_prefetch(outcome_.cells.data() + outcome_.steps + 1, 1);
  }

 private:
  const Problem* problem_;
  const Grid* grid_;
  const Grid* motion_;
  const SensorModel* sensor_;
  const WindowAtlas* windows_;
  std::uint64_t noise_seed_;
  /// Ends the episode for `why` (its cells cut to the actions taken).
  void end(const char* why);

  BudgetRule budget_;
  long action_limit_;  // budget_.actionLimit()
  int counted_ = 0;  // actions that used the budget
  Connectivity connectivity_;
  bool record_path_;
  Cell position_;
  bool bumped_ = false;
  bool done_ = false;
  EpisodeOutcome outcome_;
};

}  // namespace ppp
