#pragma once

#include <cstdint>
#include <vector>

#include "ppp_core/grid.hpp"

namespace ppp {

/// Line of sight between cell centres with a perfect sensor: true unless the open segment from `from`'s
/// centre to `to`'s centre passes through the interior of an obstacle cell other than `from` and `to`.
/// Grazing a corner or running along an edge does not block. Both cells must be on the grid.
bool lineOfSight(const Grid& grid, Cell from, Cell to);

/// The cells whose interior the open segment between the centres of `from` and `to` crosses, nearest first,
/// ends excluded (they may lie off the grid): `to` is in line of sight iff none of them is an obstacle.
std::vector<Cell> cellsCrossed(Cell from, Cell to);

/// Everything a perfect sensor sees from one cell, computed by sweeping four 90-degree cones row by row
/// and keeping the obstacles' angular shadows as exact rational intervals: each cell is visited about once,
/// and the answer equals lineOfSight() for every cell. Keeps its buffers between calls.
class VisibilitySolver {
 public:
  /// Marks the cells visible from `viewpoint` (the viewpoint included) and returns how many there are.
  int solve(const Grid& grid, Cell viewpoint);
  /// Per-cell result of the last solve(), row-major: 1 visible, 0 hidden.
  const std::vector<std::uint8_t>& visible() const { return visible_; }

 private:
  /// An open interval of slopes (minor/major), as fractions with positive denominators.
  struct Shadow {
    std::int64_t lo_num, lo_den, hi_num, hi_den;
  };
  void sweepCone(const Grid& grid, Cell viewpoint, int cone);

  std::vector<std::uint8_t> visible_;
  std::vector<Shadow> shadows_;
  std::vector<Shadow> row_shadows_;
  std::vector<Shadow> merged_;
};

/// Fraction of all grid cells visible from `viewpoint` (in [0, 1]).
double visibilityFraction(const Grid& grid, Cell viewpoint);

}  // namespace ppp
