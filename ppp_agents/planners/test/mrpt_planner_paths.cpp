// PlannerSimple2D::computePath on a free 7 x 6 map of 1 m cells (robot radius 0, every cell of a path a point),
// asked for the cell (3, 3) from two of its neighbours, and from one of them again with a wall below it. Beside
// each of MRPT's answers, the answer of the change proposed in the report: one wave from the target with the same
// step costs (2 orthogonal, 3 diagonal) grown in order of cost, then the steepest way down from the origin.
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/nav/planners/PlannerSimple2D.h>
#include <mrpt/poses/CPose2D.h>

#include <array>
#include <climits>
#include <cstdio>
#include <deque>
#include <string>
#include <utility>
#include <vector>

using Cells = std::vector<std::pair<int, int>>;

// The proposed search on `map`'s cells (occupied: probability of being free below 0.5): the cells of a path from
// (ox, oy) to (tx, ty), without the origin; empty when there is none. Every cell's value is its least cost to the
// target, so a path is shortest in these costs, and the path from any cell on it is the rest of it.
Cells proposedPath(const mrpt::maps::COccupancyGridMap2D& map, int ox, int oy, int tx, int ty) {
  const int w = static_cast<int>(map.getSizeX()), h = static_cast<int>(map.getSizeY());
  const auto free = [&](int x, int y) { return x >= 0 && y >= 0 && x < w && y < h && map.getCell(x, y) > 0.5f; };
  const std::array<std::array<int, 3>, 8> steps = {
      {{-1, 0, 2}, {1, 0, 2}, {0, -1, 2}, {0, 1, 2}, {-1, -1, 3}, {1, -1, 3}, {-1, 1, 3}, {1, 1, 3}}};
  std::vector<int> cost(static_cast<std::size_t>(w * h), INT_MAX);
  std::vector<std::vector<int>> buckets(4);  // cells by cost modulo 4: a step costs 2 or 3
  cost[static_cast<std::size_t>(tx + w * ty)] = 0;
  buckets[0].push_back(tx + w * ty);
  for (int c = 0, pending = 1; pending > 0; ++c) {
    std::vector<int> now;
    now.swap(buckets[c % 4]);
    pending -= static_cast<int>(now.size());
    for (const int i : now) {
      if (cost[static_cast<std::size_t>(i)] != c) continue;  // reached more cheaply since
      for (const auto& [dx, dy, step] : steps) {
        const int x = i % w + dx, y = i / w + dy;
        if (!free(x, y) || cost[static_cast<std::size_t>(x + w * y)] <= c + step) continue;
        cost[static_cast<std::size_t>(x + w * y)] = c + step;
        buckets[(c + step) % 4].push_back(x + w * y);
        ++pending;
      }
    }
  }
  Cells path;
  if (cost[static_cast<std::size_t>(ox + w * oy)] == INT_MAX) return path;
  for (int x = ox, y = oy; x != tx || y != ty;) {
    int best_x = x, best_y = y;
    for (const auto& [dx, dy, step] : steps) {
      if (free(x + dx, y + dy) && cost[static_cast<std::size_t>(x + dx + w * (y + dy))] + step ==
                                      cost[static_cast<std::size_t>(x + w * y)]) {
        best_x = x + dx, best_y = y + dy;
        break;
      }
    }
    x = best_x, y = best_y;
    path.emplace_back(x, y);
  }
  return path;
}

void ask(const mrpt::maps::COccupancyGridMap2D& map, const std::string& what, int ox, int oy, int tx, int ty) {
  mrpt::nav::PlannerSimple2D planner;
  planner.robotRadius = 0;
  planner.minStepInReturnedPath = 0;
  std::deque<mrpt::math::TPoint2D> path;
  bool not_found = true;
  planner.computePath(map, mrpt::poses::CPose2D(ox + 0.5, oy + 0.5, 0), mrpt::poses::CPose2D(tx + 0.5, ty + 0.5, 0),
                      path, not_found);
  std::string mrpt_text = not_found ? "notFound " : "";
  for (const auto& p : path) mrpt_text += "(" + std::to_string(static_cast<int>(p.x)) + ", " +
                                          std::to_string(static_cast<int>(p.y)) + ") ";
  std::string proposed_text;
  for (const auto& [x, y] : proposedPath(map, ox, oy, tx, ty)) {
    proposed_text += "(" + std::to_string(x) + ", " + std::to_string(y) + ") ";
  }
  std::printf("%s, cell (%d, %d) to (%d, %d): MRPT %s| proposed %s\n", what.c_str(), ox, oy, tx, ty, mrpt_text.c_str(),
              proposed_text.empty() ? "none " : proposed_text.c_str());
}

int main() {
  mrpt::maps::COccupancyGridMap2D map;
  map.setSize(0, 7, 0, 6, 1.0f, 1.0f);  // x in [0, 7), y in [0, 6), every cell free
  ask(map, "free map", 2, 2, 3, 3);
  ask(map, "free map", 3, 2, 3, 3);
  for (const int x : {2, 3, 4}) map.setCell(x, 1, 0.0f);  // a wall below (3, 2)
  ask(map, "wall below", 3, 2, 3, 3);
  return 0;
}
