#include "ppp_core/continuous_episode.hpp"

#include <cmath>
#include <string>

#include "ppp_core/episode.hpp"
#include "ppp_core/episode_reason.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {

namespace {

/// A clearance this small is contact: conservative advancement approaches contact geometrically and stops here.
constexpr double kContact = 1e-9;
/// Most advancement steps in one control period; a disc grazing a wall for longer is judged at the period's end.
constexpr int kMostAdvances = 200;

}  // namespace

Grid continuousConfigurationSpace(const SquareWorld& world, double radius) {
  const MapFrame& frame = world.frame();
  Grid space(frame.width, frame.height);
  for (int y = 0; y < frame.height; ++y) {
    for (int x = 0; x < frame.width; ++x) {
      const Cell c{x, y};
      space.setObstacle(c, world.collides(frame.centreX(c), frame.centreY(c), radius));
    }
  }
  return space;
}

long continuousStepBudget(const MotionOptions& options, int optimal_moves) {
  const double seconds = options.time_factor * optimal_moves * options.resolution / options.max_linear_speed;
  return static_cast<long>(std::ceil(seconds / options.control_period - 1e-9));
}

ContinuousEpisode::ContinuousEpisode(const Problem& problem, const Grid& grid, const MotionOptions& options,
                                     double radius_cells, long step_budget, std::uint64_t run_seed, bool record_poses)
    : world_(grid, options.resolution),
      limits_(KinematicLimits::of(options)),
      beams_(LaserBeams::of(options)),
      period_(options.control_period),
      radius_(radius_cells * options.resolution),
      goal_tolerance_(options.goal_tolerance * options.resolution),
      step_budget_(step_budget),
      patience_steps_(options.progress_timeout > 0
                          ? static_cast<long>(std::ceil(options.progress_timeout / options.control_period - 1e-9))
                          : 0),
      progress_radius_(options.progress_radius * options.resolution),
      anchor_{world_.frame().centreX(problem.start), world_.frame().centreY(problem.start)},
      goal_{world_.frame().centreX(problem.goal), world_.frame().centreY(problem.goal)},
      noise_(noiseSeed(run_seed)),
      pose_{world_.frame().centreX(problem.start), world_.frame().centreY(problem.start), 0},
      record_poses_(record_poses) {
  if (world_.collides(pose_.x, pose_.y, radius_)) {
    throw InvalidArgument("robot_radius", "a disc of " + formatShortest(radius_cells) +
                                              " cells touches an obstacle or the border at the start cell (" +
                                              std::to_string(problem.start.x) + ", " +
                                              std::to_string(problem.start.y) +
                                              "): expected a robot that can stand there");
  }
  outcome_.cells.push_back(problem.start);
  if (record_poses_) outcome_.poses.push_back(pose_);
  if (std::hypot(pose_.x - goal_.x, pose_.y - goal_.y) <= goal_tolerance_) end(reason::kGoalReached, true);
}

void ContinuousEpisode::scan(std::vector<float>* ranges) { scanLaser(world_, pose_, beams_, &noise_, ranges); }

bool ContinuousEpisode::move(const BodyVelocity& velocity) {
  const double speed = std::hypot(velocity.forward, velocity.left);
  if (speed == 0) {
    pose_ = integrate(pose_, velocity, period_);
    return false;
  }
  const Pose2D from = pose_;
  double t = 0;
  for (int i = 0; i < kMostAdvances; ++i) {
    const Pose2D at = integrate(from, velocity, t);
    const double ahead = (period_ - t) * speed;
    const double gap = world_.clearance(at.x, at.y, radius_ + ahead + 1) - radius_;
    if (gap <= kContact) {
      pose_ = at;
      outcome_.distance += t * speed;
      return true;
    }
    if (gap > ahead) break;
    t += gap / speed;
  }
  pose_ = integrate(from, velocity, period_);
  outcome_.distance += period_ * speed;
  return world_.collides(pose_.x, pose_.y, radius_);
}

void ContinuousEpisode::apply(const BodyVelocity& command) {
  if (done_) return;
  if (!std::isfinite(command.forward) || !std::isfinite(command.left) || !std::isfinite(command.turn)) {
    end(reason::kInvalidCommand, false);
    return;
  }
  velocity_ = limitVelocity(command, velocity_, limits_, period_);
  const bool touched = move(velocity_);
  ++outcome_.steps;
  outcome_.seconds = outcome_.steps * period_;
  outcome_.cells.push_back(world_.cellAt(pose_.x, pose_.y));
  if (record_poses_) outcome_.poses.push_back(pose_);
  if (touched) {
    velocity_ = BodyVelocity{};
    end(reason::kCollision, false);
  } else if (std::hypot(pose_.x - goal_.x, pose_.y - goal_.y) <= goal_tolerance_) {
    end(reason::kGoalReached, true);
  } else if (outcome_.steps >= step_budget_) {
    end(reason::kBudgetExhausted, false);
  } else if (patience_steps_ > 0) {
    if (std::hypot(pose_.x - anchor_.x, pose_.y - anchor_.y) > progress_radius_) {
      anchor_ = MapPoint{pose_.x, pose_.y};
      anchor_step_ = outcome_.steps;
    } else if (outcome_.steps - anchor_step_ >= patience_steps_) {
      end(reason::kNoProgress, false);
    }
  }
}

void ContinuousEpisode::fail(const char* reason) {
  if (!done_) end(reason, false);
}

void ContinuousEpisode::end(const char* reason, bool passed) {
  done_ = true;
  outcome_.passed = passed;
  outcome_.reason = reason;
}

}  // namespace ppp
