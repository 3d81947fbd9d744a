#include "ppp_core/reachability.hpp"

#include "ppp_core/octile.hpp"

namespace ppp {

std::vector<int> stepDistances(const Grid& grid, Cell from, Connectivity connectivity) {
  std::vector<int> distance(static_cast<std::size_t>(grid.size()), -1);
  if (!grid.isFree(from)) return distance;
  std::vector<int> queue;
  queue.reserve(static_cast<std::size_t>(grid.size()));
  distance[grid.index(from)] = 0;
  queue.push_back(grid.index(from));
  const int w = grid.width();
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int i = queue[head];
    const Cell c = grid.cellAt(i);
    const int next_distance = distance[i] + 1;
    auto visit = [&](bool inside, int j) {
      if (inside && distance[j] < 0 && grid.cells()[j] == 0) {
        distance[j] = next_distance;
        queue.push_back(j);
      }
    };
    visit(c.x > 0, i - 1);
    visit(c.x + 1 < w, i + 1);
    visit(c.y > 0, i - w);
    visit(c.y + 1 < grid.height(), i + w);
    if (connectivity != Connectivity::Eight) continue;
    for (const int dy : {-1, 1}) {
      for (const int dx : {-1, 1}) {
        if (octileMoveAllowed(grid, c, dx, dy)) visit(true, i + dy * w + dx);
      }
    }
  }
  return distance;
}

int fewestMoves(const Grid& grid, Cell start, Cell goal, Connectivity connectivity) {
  if (!grid.contains(start) || !grid.contains(goal)) return -1;
  return stepDistances(grid, start, connectivity)[grid.index(goal)];
}

bool isReachable(const Grid& grid, Cell start, Cell goal) {
  if (!grid.contains(goal)) return false;
  return stepDistances(grid, start)[grid.index(goal)] >= 0;
}

}  // namespace ppp
