#include "ppp_core/octile.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <queue>
#include <string>

#include "ppp_core/error.hpp"

namespace ppp {

namespace {

void requireOnGrid(const Grid& grid, Cell c, const char* name) {
  if (!grid.contains(c)) {
    throw InvalidArgument(name, "cell " + cellText(c) + " is off the " + std::to_string(grid.width()) + " x " +
                                    std::to_string(grid.height()) + " grid");
  }
}

}  // namespace

bool octileMoveAllowed(const Grid& grid, Cell from, int dx, int dy) {
  if (!grid.isFree(Cell{from.x + dx, from.y + dy})) return false;
  if (dx == 0 || dy == 0) return true;
  return grid.isFree(Cell{from.x + dx, from.y}) && grid.isFree(Cell{from.x, from.y + dy});
}

double octileDistance(Cell a, Cell b) {
  const int dx = std::abs(a.x - b.x);
  const int dy = std::abs(a.y - b.y);
  return std::max(dx, dy) - std::min(dx, dy) + kDiagonalCost * std::min(dx, dy);
}

OctileRoute shortestOctileRoute(const Grid& grid, Cell start, Cell goal) {
  requireOnGrid(grid, start, "start");
  requireOnGrid(grid, goal, "goal");
  OctileRoute route;
  if (!grid.isFree(start) || !grid.isFree(goal)) return route;
  const int cells = grid.size();
  std::vector<double> cost(static_cast<std::size_t>(cells), -1.0);
  std::vector<int> parent(static_cast<std::size_t>(cells), -1);
  std::vector<std::uint8_t> closed(static_cast<std::size_t>(cells), 0);
  struct Entry {
    double estimate;  // cost so far + octile distance to the goal (consistent, so a closed cell is final)
    int cell;
    bool operator>(const Entry& other) const {
      return estimate != other.estimate ? estimate > other.estimate : cell > other.cell;
    }
  };
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  cost[static_cast<std::size_t>(grid.index(start))] = 0;
  open.push({octileDistance(start, goal), grid.index(start)});
  while (!open.empty()) {
    const int i = open.top().cell;
    open.pop();
    if (closed[static_cast<std::size_t>(i)] != 0) continue;
    closed[static_cast<std::size_t>(i)] = 1;
    const Cell c = grid.cellAt(i);
    if (c == goal) break;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || !octileMoveAllowed(grid, c, dx, dy)) continue;
        const Cell n{c.x + dx, c.y + dy};
        const auto j = static_cast<std::size_t>(grid.index(n));
        const double through = cost[static_cast<std::size_t>(i)] + (dx != 0 && dy != 0 ? kDiagonalCost : 1.0);
        if (closed[j] != 0 || (cost[j] >= 0 && cost[j] <= through)) continue;
        cost[j] = through;
        parent[j] = i;
        open.push({through + octileDistance(n, goal), static_cast<int>(j)});
      }
    }
  }
  const auto g = static_cast<std::size_t>(grid.index(goal));
  if (closed[g] == 0) return route;
  route.length = cost[g];
  for (int i = static_cast<int>(g); i >= 0; i = parent[static_cast<std::size_t>(i)]) route.cells.push_back(grid.cellAt(i));
  std::reverse(route.cells.begin(), route.cells.end());
  return route;
}

}  // namespace ppp
