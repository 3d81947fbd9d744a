// PlannerSimple2D::computePath on a free 7 x 6 map of 1 m cells (robot radius 0, every cell of a path a point),
// asked for the cell (3, 3) from two of its neighbours: (2, 2), its diagonal neighbour, and (3, 2), the cell below
// it. Each path takes two steps, the first through the other neighbour.
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/nav/planners/PlannerSimple2D.h>
#include <mrpt/poses/CPose2D.h>

#include <cstdio>
#include <deque>
#include <string>

void ask(const mrpt::maps::COccupancyGridMap2D& map, int ox, int oy, int tx, int ty) {
  mrpt::nav::PlannerSimple2D planner;
  planner.robotRadius = 0;
  planner.minStepInReturnedPath = 0;
  std::deque<mrpt::math::TPoint2D> path;
  bool not_found = false;
  planner.computePath(map, mrpt::poses::CPose2D(ox + 0.5, oy + 0.5, 0), mrpt::poses::CPose2D(tx + 0.5, ty + 0.5, 0),
                      path, not_found);
  std::string text = not_found ? "notFound" : "path";
  for (const auto& p : path) {
    text += " (" + std::to_string(map.x2idx(p.x)) + ", " + std::to_string(map.y2idx(p.y)) + ")";
  }
  std::printf("free map, cell (%d, %d) to (%d, %d): %s\n", ox, oy, tx, ty, text.c_str());
}

int main() {
  mrpt::maps::COccupancyGridMap2D map;
  map.setSize(0, 7, 0, 6, 1.0f, 1.0f);  // x in [0, 7), y in [0, 6), every cell free
  ask(map, 2, 2, 3, 3);
  ask(map, 3, 2, 3, 3);
  return 0;
}
