#pragma once

#include <cstdint>
#include <vector>

#include "ppp_core/grid.hpp"
#include "ppp_core/map_frame.hpp"

namespace ppp {

/// A PPP's grid as the continuous motion model sees it, in the ROS `map` frame (metres, y up, origin at the map's
/// bottom-left corner): each obstacle cell a closed square of `resolution` metres, and the map's border a wall.
class SquareWorld {
 public:
  /// Where rays start: the index of the origin's cell among the blocked flags (-1 when off the map or in an
  /// obstacle) and the distances to its cell's four sides.
  struct Origin {
    int index = -1;                                ///< Cell index, border ring included.
    double right = 0, left = 0, up = 0, down = 0;  ///< Metres to the cell's sides.
  };
  /// The world of `grid` at `resolution` metres per cell.
  SquareWorld(const Grid& grid, double resolution);
  /// The map's frame (size and resolution).
  const MapFrame& frame() const { return frame_; }
  /// Width of the map in metres.
  double widthMetres() const { return frame_.width * frame_.resolution; }
  /// Height of the map in metres.
  double heightMetres() const { return frame_.height * frame_.resolution; }
  /// The distance from (x, y) to the nearest obstacle square or the border, or `cap` when none is nearer than
  /// `cap` (0 inside an obstacle or off the map).
  double clearance(double x, double y, double cap) const;
  /// True when a disc of `radius` metres centred at (x, y) touches an obstacle square or the border (contact
  /// counts: a clearance of exactly `radius` collides).
  bool collides(double x, double y, double radius) const { return clearance(x, y, radius + 1) <= radius; }
  /// The distance along the ray from (x, y) at `angle` (radians, counter-clockwise from +x) to the first obstacle
  /// square or the border, computed exactly (a grid traversal from crossing to crossing, not marched), or
  /// +infinity when it is farther than `max_range`. 0 when (x, y) is inside an obstacle or off the map.
  double castRay(double x, double y, double angle, double max_range) const;
  /// castRay() of many rays from (x, y): ray i along (cosines[i], sines[i]) turned by the angle whose cosine
  /// and sine are `turn_cos` and `turn_sin`, into ranges[i] (count = cosines.size()).
  void castFan(double x, double y, double turn_cos, double turn_sin, const std::vector<double>& cosines,
               const std::vector<double>& sines, double max_range, float* ranges) const;
  /// The grid cell holding the point (x, y) of the map frame (may be off the grid).
  Cell cellAt(double x, double y) const;

 private:
  /// The origin of rays from (x, y).
  Origin originAt(double x, double y) const;
  /// True when map column `column`, map row `row` (0 at the bottom; -1 to the size: the border ring) is off the
  /// map or an obstacle.
  bool blocked(int column, int row) const { return blocked_[(row + 1) * stride_ + column + 1] != 0; }

  MapFrame frame_;
  int stride_;                          // columns of blocked_: the map's and the border ring's
  std::vector<std::uint8_t> blocked_;   // map-frame rows, bottom first, with a ring of blocked cells around
};

}  // namespace ppp
