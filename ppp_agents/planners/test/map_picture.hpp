#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "grid_map.hpp"
#include "ppp_core/map_frame.hpp"

namespace ppp {
namespace planners {
namespace test {

/// nav_msgs/OccupancyGrid data (row 0 at the bottom) of a map drawn top row first: '#' obstacle (100),
/// '?' unknown (-1), anything else free (0).
inline std::vector<std::int8_t> occupancyData(const std::vector<std::string>& rows) {
  const int width = static_cast<int>(rows.front().size());
  const int height = static_cast<int>(rows.size());
  const MapFrame frame{width, height, 1.0};
  std::vector<std::int8_t> data(static_cast<std::size_t>(width * height), 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const char c = rows[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)];
      data[static_cast<std::size_t>(frame.mapIndex(Cell{x, y}))] = c == '#' ? 100 : c == '?' ? -1 : 0;
    }
  }
  return data;
}

/// The GridMap of a drawn map (see occupancyData).
inline GridMap mapPicture(const std::vector<std::string>& rows, bool unknown_is_free = true, double resolution = 1.0) {
  return GridMap(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()), resolution, occupancyData(rows),
                 unknown_is_free);
}

/// The robot's own world of a drawn map: '#' cells are obstacles, everything else free.
inline Grid pictureGrid(const std::vector<std::string>& rows) {
  Grid grid(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()));
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      grid.setObstacle(Cell{x, y}, rows[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] == '#');
    }
  }
  return grid;
}

/// The cell of the first `mark` in a drawn map.
inline Cell markedCell(const std::vector<std::string>& rows, char mark) {
  for (std::size_t y = 0; y < rows.size(); ++y) {
    const std::size_t x = rows[y].find(mark);
    if (x != std::string::npos) return Cell{static_cast<int>(x), static_cast<int>(y)};
  }
  return Cell{-1, -1};
}

}  // namespace test
}  // namespace planners
}  // namespace ppp
