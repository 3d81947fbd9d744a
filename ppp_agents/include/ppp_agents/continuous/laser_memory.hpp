#pragma once

#include <cstdint>
#include <vector>

#include "ppp_core/kinematics.hpp"
#include "ppp_core/laser.hpp"
#include "ppp_core/map_frame.hpp"

namespace ppp {
namespace agents {

/// The map a robot in continuous motion builds of a PPP's cells from its laser, as the planner bridge gives it to a
/// path planner that has no prior map: every cell unknown at first but the start's; each beam marks free every
/// cell it crosses before its return (or up to its maximum range), and marks an obstacle the cell just beyond a
/// return on the face of a square (a return within kCornerTolerance of a cell corner marks nothing: the square it
/// touched is ambiguous, and a beam along the next face will mark it). Without noise the map is exact: a beam
/// stops at the first closed square it touches, so every cell it crosses before is free. A cell once marked an
/// obstacle stays one.
class LaserMemory {
 public:
  /// Fraction of a cell within which a return counts as at a corner of the grid.
  static constexpr double kCornerTolerance = 1e-3;

  /// A new run on a map of `frame`'s size, every cell unknown but the one holding `start` (free).
  void start(const MapFrame& frame, const Pose2D& start);
  /// Adds the scan `ranges` (+infinity: no return) of `beams` taken at `pose`.
  /// @return true when a cell became known or turned into an obstacle.
  bool add(const Pose2D& pose, const std::vector<float>& ranges, const LaserBeams& beams);
  /// The map, one value per grid cell in grid order (row 0 at the top): kScanUnknown, kScanFree or kScanObstacle.
  const std::vector<std::int8_t>& cells() const { return cells_; }
  /// The value of the cell at map-frame column `column` and row `row` (0 at the bottom), which must be on the map.
  std::int8_t at(int column, int row) const { return cells_[index(column, row)]; }

 private:
  int index(int column, int row) const { return (frame_.height - 1 - row) * frame_.width + column; }
  bool onMap(int column, int row) const { return column >= 0 && row >= 0 && column < frame_.width && row < frame_.height; }
  /// Marks free every cell the segment from (x, y) along (dx, dy) crosses up to `length` metres.
  bool markCrossed(double x, double y, double dx, double dy, double length);
  /// Marks an obstacle the cell holding the point just beyond a return at (x, y) along (dx, dy).
  bool markReturn(double x, double y, double dx, double dy);

  MapFrame frame_;
  std::vector<std::int8_t> cells_;
};

}  // namespace agents
}  // namespace ppp
