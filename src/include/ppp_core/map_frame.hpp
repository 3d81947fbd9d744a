#pragma once

#include "ppp_core/grid.hpp"

namespace ppp {

/// A point of the ROS `map` frame, in metres.
struct MapPoint {
  double x = 0.0;  ///< Metres to the right of the map's origin (its bottom-left corner).
  double y = 0.0;  ///< Metres above the map's origin.
};

/// The one place where grid coordinates (y down, row 0 at the top) meet the ROS `map` frame
/// (y up, origin at the bottom-left corner of the map, `resolution` metres per cell).
struct MapFrame {
  int width = 0;            ///< Grid columns.
  int height = 0;           ///< Grid rows.
  double resolution = 1.0;  ///< Metres per cell.

  /// Row-major index into a map-frame array (nav_msgs/OccupancyGrid data, row 0 at the bottom).
  int mapIndex(Cell c) const { return (height - 1 - c.y) * width + c.x; }
  /// Map-frame row of a grid cell (0 at the bottom).
  int mapRow(Cell c) const { return height - 1 - c.y; }
  /// Grid cell of a map-frame column and row.
  Cell cellOfMapRowColumn(int column, int row) const { return Cell{column, height - 1 - row}; }
  /// Map-frame x, in metres, of the cell's centre.
  double centreX(Cell c) const { return (c.x + 0.5) * resolution; }
  /// Map-frame y, in metres, of the cell's centre.
  double centreY(Cell c) const { return (mapRow(c) + 0.5) * resolution; }
};

}  // namespace ppp
