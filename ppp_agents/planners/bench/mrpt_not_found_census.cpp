// How often MRPT's PlannerSimple2D::computePath answers notFound although a path exists, counted over random maps
// by the distance between origin and target (in cells, the larger of |dx| and |dy|):
//  1. 1 m cells, robot radius 0, every pair of free cells off the map's outer ring (which computePath never enters)
//     that an 8-connected route of such cells joins without cutting a corner;
//  2. as the repository's planner node asks it: a 20 x 20 grid of free and blocked cells drawn 4 map cells to a
//     cell, obstacles grown by one map cell, from the centre of every cell that a route of cells joins to the
//     goal in the corner (19, 19), as the robot's cell would be at each step.
// Usage: mrpt_not_found_census [MAPS]   (MAPS random maps per part, 200 by default; seeded, so the counts repeat)
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/nav/planners/PlannerSimple2D.h>
#include <mrpt/poses/CPose2D.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <map>
#include <random>
#include <vector>

namespace {

struct Counts {
  std::map<int, long> asked, not_found;
};

/// Cells of a w x h grid joined to (x0, y0) by 8-connected steps over `usable` cells that cut no corner.
template <class Usable>
std::vector<char> joined(int w, int h, int x0, int y0, Usable usable) {
  std::vector<char> seen(static_cast<std::size_t>(w * h), 0);
  std::deque<int> queue{x0 + w * y0};
  seen[static_cast<std::size_t>(x0 + w * y0)] = 1;
  while (!queue.empty()) {
    const int x = queue.front() % w, y = queue.front() / w;
    queue.pop_front();
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if (!usable(x + dx, y + dy) || seen[static_cast<std::size_t>(x + dx + w * (y + dy))]) continue;
        if (dx != 0 && dy != 0 && (!usable(x + dx, y) || !usable(x, y + dy))) continue;
        seen[static_cast<std::size_t>(x + dx + w * (y + dy))] = 1;
        queue.push_back(x + dx + w * (y + dy));
      }
    }
  }
  return seen;
}

bool notFound(const mrpt::maps::COccupancyGridMap2D& map, float radius, double ox, double oy, double tx, double ty) {
  mrpt::nav::PlannerSimple2D planner;
  planner.robotRadius = radius;
  planner.minStepInReturnedPath = 0;
  std::deque<mrpt::math::TPoint2D> path;
  bool not_found = true;
  planner.computePath(map, mrpt::poses::CPose2D(ox, oy, 0), mrpt::poses::CPose2D(tx, ty, 0), path, not_found);
  return not_found;
}

std::vector<char> randomCells(std::mt19937& rng, int w, int h, double density) {
  std::bernoulli_distribution blocked(density);
  std::vector<char> cells(static_cast<std::size_t>(w * h));
  for (char& c : cells) c = blocked(rng) ? 1 : 0;
  return cells;
}

void fineMaps(int maps, Counts* counts) {
  const int w = 12, h = 12;
  std::mt19937 rng(1);
  for (int m = 0; m < maps; ++m) {
    const std::vector<char> blocked = randomCells(rng, w, h, 0.1 + 0.1 * (m % 5));
    mrpt::maps::COccupancyGridMap2D map;
    map.setSize(0, w, 0, h, 1.0f, 1.0f);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) map.setCell(x, y, blocked[static_cast<std::size_t>(x + w * y)] ? 0.0f : 1.0f);
    }
    const auto usable = [&](int x, int y) {
      return x >= 1 && y >= 1 && x < w - 1 && y < h - 1 && !blocked[static_cast<std::size_t>(x + w * y)];
    };
    for (int oy = 0; oy < h; ++oy) {
      for (int ox = 0; ox < w; ++ox) {
        if (!usable(ox, oy)) continue;
        const std::vector<char> reach = joined(w, h, ox, oy, usable);
        for (int t = 0; t < w * h; ++t) {
          if (!reach[static_cast<std::size_t>(t)] || t == ox + w * oy) continue;
          const int d = std::max(std::abs(t % w - ox), std::abs(t / w - oy));
          ++counts->asked[d];
          counts->not_found[d] += notFound(map, 0.0f, ox + 0.5, oy + 0.5, t % w + 0.5, t / w + 0.5);
        }
      }
    }
  }
}

void plannerNodeMaps(int maps, Counts* counts) {
  const int n = 20, scale = 4;
  std::mt19937 rng(2);
  for (int m = 0; m < maps; ++m) {
    std::vector<char> blocked = randomCells(rng, n, n, 0.1 + 0.05 * (m % 5));
    blocked[0] = blocked[n * n - 1] = 0;  // start and goal
    mrpt::maps::COccupancyGridMap2D map;
    map.setSize(0, n * scale, 0, n * scale, 1.0f, 1.0f);
    for (int y = 0; y < n * scale; ++y) {  // map y up: cell row n - 1 - y / scale
      for (int x = 0; x < n * scale; ++x) {
        map.setCell(x, y, blocked[static_cast<std::size_t>(x / scale + n * (n - 1 - y / scale))] ? 0.0f : 1.0f);
      }
    }
    const auto usable = [&](int x, int y) {
      return x >= 0 && y >= 0 && x < n && y < n && !blocked[static_cast<std::size_t>(x + n * y)];
    };
    const std::vector<char> reach = joined(n, n, n - 1, n - 1, usable);
    const auto centre = [&](int cell) { return (cell + 0.5) * scale; };
    for (int c = 0; c < n * n - 1; ++c) {
      if (!reach[static_cast<std::size_t>(c)]) continue;
      const int d = std::max(n - 1 - c % n, n - 1 - c / n) * scale;
      ++counts->asked[d];
      counts->not_found[d] +=
          notFound(map, 1.0f, centre(c % n), centre(n - 1 - c / n), centre(n - 1), centre(0));
    }
  }
}

void print(const char* title, const Counts& counts) {
  std::printf("%s\n", title);
  for (const auto& [d, asked] : counts.asked) {
    const long wrong = counts.not_found.count(d) ? counts.not_found.at(d) : 0;
    std::printf("  distance %2d: %8ld asked, %6ld notFound (%.4f %%)\n", d, asked, wrong, 100.0 * wrong / asked);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int maps = argc > 1 ? std::atoi(argv[1]) : 200;
  if (maps < 1) {
    std::fprintf(stderr, "MAPS: expected a positive count of maps, got '%s'\n", argv[1]);
    return 2;
  }
  Counts fine, node;
  fineMaps(maps, &fine);
  print("1 m cells, radius 0, pairs joined off the outer ring:", fine);
  plannerNodeMaps(maps, &node);
  print("the planner node's maps (4 map cells a cell, grown by 1), to the goal in the corner:", node);
  return 0;
}
