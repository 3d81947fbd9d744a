#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ppp_agents/state_digest.hpp"
#include "ppp_core/action.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/map_frame.hpp"

namespace ppp {
namespace agents {

/// What a robot knows of its map: kScanFree, kScanObstacle or kScanUnknown per cell, row-major grid order.
struct KnownMap {
  int width = 0;                    ///< Columns.
  int height = 0;                   ///< Rows.
  std::vector<std::int8_t> cells;   ///< One kScan* value per cell.
  /// The value of a cell (kScanOutOfBounds off the map).
  std::int8_t at(Cell c) const;
};

/// A planner's path, turned into one move per step: the waypoints are joined by walkMapSegment (the cells the
/// straight segments pass through, 4-connected), the robot advances one cell of that walk per step, and the
/// True when two paths have the same points, exactly (a planner sent the path being followed again).
bool samePoints(const std::vector<MapPoint>& a, const std::vector<MapPoint>& b);

/// follower asks for a re-plan when the robot leaves the walk or its next cell is known to be an obstacle.
class PathFollower {
 public:
  /// Checks a planner's path and, when it is usable, follows it from now on. Usable: the walk stays on the map,
  /// passes through the robot's cell, has no obstacle of `known` after it, and ends at `goal`. Returns what is
  /// wrong ("" when the path was taken); an empty waypoint list is reported as "the path is empty".
  std::string follow(const std::vector<MapPoint>& waypoints, const MapFrame& frame, Cell robot, Cell goal,
                     const KnownMap& known);
  /// The move that takes the robot from `robot` to the next cell of the path, or nothing when a re-plan is due:
  /// the path is used up, the robot left it, or the next cell is an obstacle in `known`. A robot that bumped
  /// (still on its cell) is sent the same move again. Under connectivity 8, where the walk turns a corner whose
  /// two sides `known` shows free, it cuts across with the diagonal move (two cells of the walk in one move).
  std::optional<Action> next(Cell robot, const KnownMap& known);
  /// Forgets the path.
  void clear();
  /// Adds the follower's whole state (the walk and the robot's place on it) to `digest`.
  void addTo(StateDigest* digest) const;
  /// Sets the move model (4 or 8) of the moves next() gives; 4 until set.
  void setConnectivity(Connectivity connectivity) { connectivity_ = connectivity; }

 private:
  std::vector<Cell> walk_;
  std::size_t position_ = 0;  // index of the robot's cell in walk_
  Connectivity connectivity_ = Connectivity::Four;
};

}  // namespace agents
}  // namespace ppp
