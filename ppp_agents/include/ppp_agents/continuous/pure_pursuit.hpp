#pragma once

#include <cstddef>
#include <vector>

#include "ppp_core/kinematics.hpp"
#include "ppp_core/map_frame.hpp"

namespace ppp {
namespace agents {

/// Look-ahead of the pure pursuit follower, in PPP cells (at least twice the distance of a control period at top
/// speed).
constexpr double kLookAheadCells = 0.5;
/// The follower counts a turn of its path as reached this near it, in cells.
constexpr double kTurnReachedCells = 0.002;
/// A diff-drive robot turns on the spot until its look-ahead point is this near ahead.
constexpr double kTurnAlignedRadians = 0.05;

/// Follows a path of map-frame points in continuous motion by pure pursuit (Coulter, 1992), cutting no corner:
/// the look-ahead point is kLookAheadCells (or twice a period's distance at top speed) further along the path than
/// the robot's nearest point on it (which only moves forward), but waits at the path's next turn until the robot
/// stands within kTurnReachedCells of it at rest (and never again at a turn so reached). A holonomic robot drives straight at it; a diff-drive robot
/// steers the arc through it, or turns on the spot until it lies within kTurnAlignedRadians ahead. Speeds respect
/// the limits and slow down to stop at the next turn or the end (braking a x T a control period T:
/// v^2 / 2a + v T / 2 <= d, and never faster than reaches it in one period) and at the heading it turns to
/// (likewise with the angular acceleration).
class PurePursuit {
 public:
  /// Follows `path` (at least one point) at `resolution` metres per cell under `limits`, commanded every
  /// `control_period` seconds.
  void follow(std::vector<MapPoint> path, double resolution, const KinematicLimits& limits, double control_period);
  /// The velocity command for a robot at `pose` moving at `velocity`.
  BodyVelocity command(const Pose2D& pose, const BodyVelocity& velocity);
  /// The path's segment holding the robot's nearest point at the last command (0 before the first).
  std::size_t segment() const { return segment_; }

 private:
  /// The point `distance` metres along the path from the start of segment `segment` at fraction `along`.
  MapPoint pointAhead(std::size_t segment, double along, double distance) const;

  std::vector<MapPoint> path_;
  std::vector<double> remaining_;  // path length from each point to the end
  std::vector<bool> turns_;        // whether the path changes direction at each point
  double resolution_ = 1;
  double control_period_ = 0.1;
  std::size_t segment_ = 0;        // the segment holding the robot's nearest point
  std::size_t passed_ = 0;         // the last turn reached at rest (0: none)
  double left_ = 0;                // path length left from the robot's nearest point at the last command
  double look_ahead_ = 0.5;
  KinematicLimits limits_;
};

}  // namespace agents
}  // namespace ppp
