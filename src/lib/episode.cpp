#include "ppp_core/episode.hpp"

#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/octile.hpp"
#include "ppp_core/sensor.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {

double pathLength(const EpisodeOutcome& outcome) {
  return outcome.path_length + outcome.diagonal_moves * (kDiagonalCost - 1);
}

std::uint64_t agentSeed(std::uint64_t run_seed) { return deriveSeed(run_seed, {1}); }

std::uint64_t noiseSeed(std::uint64_t run_seed) { return deriveSeed(run_seed, {2}); }

Episode::Episode(const Problem& problem, const Grid& grid, const SensorModel& sensor, std::uint64_t run_seed,
                 BudgetRule budget, Connectivity connectivity, bool record_path, const WindowAtlas* windows,
                 const Grid* motion)
    : problem_(&problem),
      grid_(&grid),
      motion_(motion != nullptr ? motion : &grid),
      sensor_(&sensor),
      windows_(windows),
      noise_seed_(noiseSeed(run_seed)),
      budget_(budget),
      action_limit_(budget.actionLimit()),
      connectivity_(connectivity),
      record_path_(record_path),
      position_(problem.start) {
  if (record_path_) outcome_.path.push_back(position_);
  // One cell per action up to the action limit, stored by index (no growth check per step), cut to the actions
  // taken when the episode ends.
  outcome_.cells.resize(static_cast<std::size_t>(action_limit_) + 1);
  outcome_.cells[0] = position_;
}

Scan Episode::scan() const {
  return Scan(*sensor_, *grid_, position_, problem_->goal, bumped_, outcome_.steps, noise_seed_, windows_);
}

void Episode::apply(Action action) {
  if (done_) return;
  ++outcome_.steps;
  bumped_ = false;
  bool counts = action != Action::Stay || budget_.stays_count;
  const bool diagonal = isDiagonal(action);
  if (diagonal && connectivity_ != Connectivity::Eight) {
    outcome_.cells[static_cast<std::size_t>(outcome_.steps)] = position_;
    fail(reason::kInvalidAction);
    return;
  }
  if (action != Action::Stay) {
    const Cell d = offset(action);
    const Cell next{position_.x + d.x, position_.y + d.y};
    // A straight move needs a free target; a diagonal also both cells beside it.
    if (diagonal ? octileMoveAllowed(*motion_, position_, d.x, d.y) : motion_->isFree(next)) {
      position_ = next;
      ++outcome_.path_length;
      if (diagonal) ++outcome_.diagonal_moves;
      if (record_path_) outcome_.path.push_back(position_);
    } else {
      bumped_ = true;
      ++outcome_.bumps;
      counts = budget_.bumps_count;
    }
  }
  outcome_.cells[static_cast<std::size_t>(outcome_.steps)] = position_;
  if (counts) ++counted_;
  if (position_ == problem_->goal) {
    outcome_.passed = true;
    end(reason::kGoalReached);
  } else if (counted_ >= budget_.budget) {
    end(reason::kBudgetExhausted);
  } else if (outcome_.steps >= action_limit_) {
    end(reason::kActionLimit);
  }
}

void Episode::fail(const char* why) {
  if (done_) return;
  outcome_.passed = false;
  end(why);
}

void Episode::end(const char* why) {
  outcome_.reason = why;
  outcome_.cells.resize(static_cast<std::size_t>(outcome_.steps) + 1);
  done_ = true;
}

}  // namespace ppp
