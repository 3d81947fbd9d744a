#include "optimistic_astar.hpp"

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <queue>
#include <tuple>

namespace ppp {
namespace planners {

std::vector<Cell> optimisticAStar(const GridMap& map, Cell start, Cell goal) {
  return gridAStar(map, start, goal, SearchRules{});
}

std::vector<Cell> gridAStar(const GridMap& map, Cell start, Cell goal, const SearchRules& rules) {
  const auto can_step = [&](Cell from, Cell to) {
    return map.contains(to) && (rules.can_step ? rules.can_step(from, to) : map.passable(to));
  };
  if (!map.contains(start) || !map.passable(goal)) return {};
  const int width = map.frame().width;
  const int cells = width * map.frame().height;
  const auto index = [width](Cell c) { return c.y * width + c.x; };
  const auto heuristic = [&goal](Cell c) { return manhattanDistance(c, goal); };

  std::vector<int> cost(static_cast<std::size_t>(cells), -1);
  std::vector<int> parent(static_cast<std::size_t>(cells), -1);
  // Open list entries (cost + heuristic, heuristic, cell index): the smallest wins, so ties go to the cell
  // nearer the goal, then to the smaller index.
  using Entry = std::tuple<int, int, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  cost[static_cast<std::size_t>(index(start))] = 0;
  open.emplace(heuristic(start), heuristic(start), index(start));
  constexpr Cell kSteps[] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  long expansions = 0;
  while (!open.empty()) {
    const auto [f, h, i] = open.top();
    open.pop();
    const Cell cell{i % width, i / width};
    const int g = cost[static_cast<std::size_t>(i)];
    if (f != g + h) continue;  // a stale entry: the cell was reached more cheaply since
    if (cell == goal) break;
    if (rules.max_expansions > 0 && ++expansions > rules.max_expansions) return {};
    for (const Cell step : kSteps) {
      const Cell next{cell.x + step.x, cell.y + step.y};
      if (!can_step(cell, next)) continue;
      const std::size_t j = static_cast<std::size_t>(index(next));
      if (cost[j] >= 0 && cost[j] <= g + 1) continue;
      cost[j] = g + 1;
      parent[j] = i;
      open.emplace(g + 1 + heuristic(next), heuristic(next), index(next));
      if (rules.max_open > 0 && static_cast<long>(open.size()) > rules.max_open) return {};
    }
  }
  if (cost[static_cast<std::size_t>(index(goal))] < 0) return {};
  std::vector<Cell> path;
  for (int i = index(goal); i >= 0; i = parent[static_cast<std::size_t>(i)]) path.push_back(Cell{i % width, i / width});
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace planners
}  // namespace ppp
