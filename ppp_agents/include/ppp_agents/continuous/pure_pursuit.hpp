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
/// A diff-drive robot whose look-ahead point is more than this many radians off its heading turns on the spot.
constexpr double kTurnOnTheSpot = 0.7853981633974483;

/// A robot stopping at a path's turns counts a turn as reached this near it, in cells.
constexpr double kTurnReachedCells = 0.002;
/// A diff-drive robot stopping at a path's turns turns on the spot until its look-ahead point is this near ahead.
constexpr double kTurnAlignedRadians = 0.05;

/// Follows a path of map-frame points in continuous motion by pure pursuit (Coulter, 1992): the look-ahead point
/// is kLookAheadCells (or twice a period's distance at top speed) further along the path than the robot's nearest point on it (which only moves forward). A
/// holonomic robot drives straight at it; a diff-drive robot steers the arc through it, or turns on the spot when
/// it lies more than kTurnOnTheSpot off its heading. Speeds respect the limits and slow down to stop at the path's
/// end (braking a x T a control period T: v^2 / 2a + v T / 2 <= d) and at the heading it turns to (likewise with
/// the angular acceleration). Told to stop at turns, it cuts no corner: the look-ahead point waits at the path's
/// next turn until the robot stands within kTurnReachedCells of it at rest, the robot slows to stop there (never
/// faster than reaches it in one control period), and a diff-drive robot turns on the spot until within
/// kTurnAlignedRadians of its new direction (never faster than turns it there in one period).
class PurePursuit {
 public:
  /// Follows `path` (at least one point) at `resolution` metres per cell under `limits`, commanded every
  /// `control_period` seconds, stopping at its turns or not.
  void follow(std::vector<MapPoint> path, double resolution, const KinematicLimits& limits,
              bool stop_at_turns = false, double control_period = 0.1);
  /// The velocity command for a robot at `pose` moving at `velocity`.
  BodyVelocity command(const Pose2D& pose, const BodyVelocity& velocity);
  /// True when a path is being followed.
  bool following() const { return !path_.empty(); }

 private:
  /// The point `distance` metres along the path from the start of segment `segment` at fraction `along`.
  MapPoint pointAhead(std::size_t segment, double along, double distance) const;

  std::vector<MapPoint> path_;
  std::vector<double> remaining_;  // path length from each point to the end
  std::vector<bool> turns_;        // whether the path changes direction at each point (stop_at_turns only)
  double resolution_ = 1;
  bool stop_at_turns_ = false;
  double control_period_ = 0.1;
  std::size_t segment_ = 0;        // the segment holding the robot's nearest point
  double look_ahead_ = 0.5;
  KinematicLimits limits_;
};

}  // namespace agents
}  // namespace ppp
