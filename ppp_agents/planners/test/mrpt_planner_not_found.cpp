// PlannerSimple2D::computePath asked for paths that exist, where its two waves (from the origin and from the target)
// meet before either has grown: from a cell to its neighbour with a wall below the origin, from a cell to its
// neighbour in a corridor one cell wide, and from the corridor's dead end to the cell two along. Each time it says
// notFound. For contrast, the same calls where a wave grows first: without the wall, and one cell off the dead end.
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/nav/planners/PlannerSimple2D.h>
#include <mrpt/poses/CPose2D.h>

#include <cstdio>
#include <deque>
#include <string>

void ask(const mrpt::maps::COccupancyGridMap2D& map, const char* what, int ox, int oy, int tx, int ty) {
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
  std::printf("%s, cell (%d, %d) to (%d, %d): %s\n", what, ox, oy, tx, ty, text.c_str());
}

int main() {
  mrpt::maps::COccupancyGridMap2D room;  // 7 x 6 free cells of 1 m: x in [0, 7), y in [0, 6)
  room.setSize(0, 7, 0, 6, 1.0f, 1.0f);
  ask(room, "free room", 3, 2, 3, 3);
  for (const int x : {2, 3, 4}) room.setCell(x, 1, 0.0f);  // a wall below (3, 2)
  ask(room, "wall below", 3, 2, 3, 3);

  mrpt::maps::COccupancyGridMap2D corridor;  // 7 x 3 cells, free only from (1, 1) to (5, 1)
  corridor.setSize(0, 7, 0, 3, 1.0f, 1.0f);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 7; ++x) corridor.setCell(x, y, y == 1 && x >= 1 && x <= 5 ? 1.0f : 0.0f);
  }
  ask(corridor, "corridor", 3, 1, 4, 1);
  ask(corridor, "corridor", 1, 1, 3, 1);
  ask(corridor, "corridor", 2, 1, 4, 1);
  return 0;
}
