#include "grid_map.hpp"

#include <cmath>
#include <cstddef>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/footprint.hpp"
#include "ppp_core/segment_walk.hpp"

namespace ppp {
namespace planners {

GridMap::GridMap(int width, int height, double resolution, const std::vector<std::int8_t>& data, bool unknown_is_free,
                 double inflation)
    : frame_{width, height, resolution} {
  validateGridSize(width, height, "map size");
  if (!(resolution > 0.0) || !std::isfinite(resolution)) {
    throw InvalidArgument("map resolution",
                          "expected a positive, finite number of metres per cell, got " + std::to_string(resolution));
  }
  const std::size_t cells = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (data.size() != cells) {
    throw InvalidArgument(
        "map data", "expected width*height = " + std::to_string(cells) + " values, got " + std::to_string(data.size()));
  }
  passable_.assign(cells, 0);
  const bool inflating = !isPointRobot(inflation);
  Grid obstacles = inflating ? Grid(width, height) : Grid();  // the known obstacles, y down, for the inflation
  for (std::size_t i = 0; i < cells; ++i) {
    const int value = data[i];
    if (value < kUnknownOccupancy || value > 100) {
      throw InvalidArgument("map data[" + std::to_string(i) + "]",
                            "expected -1 (unknown) or an occupancy in [0, 100], got " + std::to_string(value));
    }
    const bool free = value == kUnknownOccupancy ? unknown_is_free : value < kObstacleOccupancy;
    const Cell cell = frame_.cellOfMapRowColumn(static_cast<int>(i % static_cast<std::size_t>(width)),
                                                static_cast<int>(i / static_cast<std::size_t>(width)));
    passable_[static_cast<std::size_t>(index(cell))] = free ? 1 : 0;
    if (inflating) obstacles.setObstacle(cell, value >= kObstacleOccupancy);
  }
  if (!inflating) return;
  const Grid space = configurationSpace(obstacles, inflation);
  for (int i = 0; i < static_cast<int>(cells); ++i) passable_[static_cast<std::size_t>(i)] &= space.isFree(space.cellAt(i)) ? 1 : 0;
}

Cell GridMap::cellOf(MapPoint p) const { return walkMapSegment(frame_, p.x, p.y, p.x, p.y).front(); }

bool GridMap::segmentPassable(MapPoint a, MapPoint b) const { return walkPassable(a, b) && walkPassable(b, a); }

bool GridMap::pathPasses(const std::vector<MapPoint>& path, Cell cell) const {
  for (std::size_t i = 1; i < path.size(); ++i) {
    for (const Cell passed : walkMapSegment(frame_, path[i - 1].x, path[i - 1].y, path[i].x, path[i].y)) {
      if (passed == cell) return true;
    }
  }
  return false;
}

bool GridMap::walkPassable(MapPoint from, MapPoint to) const {
  for (const Cell cell : walkMapSegment(frame_, from.x, from.y, to.x, to.y)) {
    if (!passable(cell)) return false;
  }
  return true;
}

}  // namespace planners
}  // namespace ppp
