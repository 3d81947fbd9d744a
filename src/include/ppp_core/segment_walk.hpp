#pragma once

#include <vector>

#include "ppp_core/grid.hpp"
#include "ppp_core/map_frame.hpp"

namespace ppp {

/// The cells a straight segment passes through, in order from (x0, y0)'s cell to (x1, y1)'s cell.
/// Coordinates are in grid cell units (x right, y down; cell (i, j) spans [i, i+1) x [j, j+1), so a point on
/// a cell boundary belongs to the cell with the larger index). Consecutive cells share an edge; where the
/// segment passes exactly through a cell corner, the cell reached by the x step comes first. Corners and
/// boundaries are decided exactly for the given doubles. A zero-length segment gives its one cell.
/// @throws InvalidArgument when a coordinate is not finite or lies more than 65536 cells from the origin.
std::vector<Cell> walkSegment(double x0, double y0, double x1, double y1);

/// walkSegment for a segment between two points of the ROS `map` frame (metres, y up, origin at the map's
/// bottom-left corner), converted to grid cell units through `frame` (so a point on a horizontal cell boundary
/// belongs to the cell below it: the larger grid row). Planners and the planner bridge both expand paths with
/// this function, so they agree on every cell. @throws InvalidArgument as walkSegment.
std::vector<Cell> walkMapSegment(const MapFrame& frame, double x0, double y0, double x1, double y1);

}  // namespace ppp
