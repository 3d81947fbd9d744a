#include "ppp_core/footprint.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace ppp {

namespace {

/// Tolerance of the overlap test: a disc that only touches a cell's side does not overlap it.
constexpr double kTouch = 1e-9;

}  // namespace

bool isPointRobot(double radius) { return radius <= 0.5 + kTouch; }

std::vector<Cell> footprintOffsets(double radius) {
  std::vector<Cell> offsets;
  const int reach = static_cast<int>(std::ceil(radius));
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      // Distance from the centre of cell (0, 0) to the nearest point of cell (dx, dy).
      const double gap = std::hypot(std::max(std::abs(dx) - 0.5, 0.0), std::max(std::abs(dy) - 0.5, 0.0));
      if (gap < radius - kTouch) offsets.push_back(Cell{dx, dy});
    }
  }
  return offsets;
}

const Grid& motionGrid(const Grid& grid, double radius, Grid* space) {
  if (isPointRobot(radius)) return grid;
  *space = configurationSpace(grid, radius);
  return *space;
}

Grid configurationSpace(const Grid& grid, double radius) {
  if (isPointRobot(radius)) return grid;
  const std::vector<Cell> offsets = footprintOffsets(radius);
  Grid space(grid.width(), grid.height());
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      bool free = true;
      for (const Cell& d : offsets) free = free && grid.isFree(Cell{x + d.x, y + d.y});
      space.setObstacle(Cell{x, y}, !free);
    }
  }
  return space;
}

}  // namespace ppp
