// PlannerSimple2D::computePath asked for a goal one cell beyond the top edge of a free 7 x 6 map of 1 m cells.
// Its header says a start or goal off the map gives notFound; MRPT returns notFound, but only after writing the
// goal's mark 12 bytes past the end of its 168-byte grid (run under valgrind to see it).
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/nav/planners/PlannerSimple2D.h>
#include <mrpt/poses/CPose2D.h>

#include <cstdio>
#include <deque>

int main() {
  mrpt::maps::COccupancyGridMap2D map;
  map.setSize(0, 7, 0, 6, 1.0f, 1.0f);  // x in [0, 7), y in [0, 6), every cell free
  mrpt::nav::PlannerSimple2D planner;
  planner.robotRadius = 0;
  std::deque<mrpt::math::TPoint2D> path;
  bool not_found = false;
  planner.computePath(map, mrpt::poses::CPose2D(2.5, 2.5, 0), mrpt::poses::CPose2D(3.5, 6.5, 0), path, not_found);
  std::printf("notFound %s, %zu path points\n", not_found ? "true" : "false", path.size());
  return 0;
}
