#include "ppp_core/shrink.hpp"

#include <algorithm>
#include <vector>

#include "ppp_core/error.hpp"

namespace ppp {

namespace {

/// The items of `items` whose positions are not in [begin, end).
template <typename Item>
std::vector<Item> without(const std::vector<Item>& items, std::size_t begin, std::size_t end) {
  std::vector<Item> kept(items.begin(), items.begin() + static_cast<std::ptrdiff_t>(begin));
  kept.insert(kept.end(), items.begin() + static_cast<std::ptrdiff_t>(end), items.end());
  return kept;
}

/// Delta debugging by complements: removes chunks of `items` (halves, then quarters, ... then single items) as
/// long as `holds` stays true for what is left. On return no single item can be removed.
template <typename Item>
std::vector<Item> removeWhilePossible(std::vector<Item> items, const std::function<bool(const std::vector<Item>&)>& holds) {
  std::size_t parts = 2;
  while (!items.empty()) {
    const std::size_t chunk = (items.size() + parts - 1) / parts;
    bool removed = false;
    for (std::size_t begin = 0; begin < items.size(); begin += chunk) {
      std::vector<Item> candidate = without(items, begin, std::min(begin + chunk, items.size()));
      if (holds(candidate)) {
        items = std::move(candidate);
        parts = std::max<std::size_t>(parts - 1, 2);
        removed = true;
        break;
      }
    }
    if (removed) continue;
    if (chunk == 1) break;  // every single item was tried
    parts = std::min(parts * 2, items.size());
  }
  return items;
}

/// Counts the questions asked and asks `stop` before each.
class Judge {
 public:
  Judge(const StillFails& still_fails, const StopCheck& stop) : still_fails_(still_fails), stop_(stop) {}
  bool operator()(const Problem& candidate) {
    stopIfAsked(stop_);
    ++evaluations_;
    return still_fails_(candidate);
  }
  int evaluations() const { return evaluations_; }

 private:
  const StillFails& still_fails_;
  const StopCheck& stop_;
  int evaluations_ = 0;
};

Problem withObstacles(const Problem& problem, std::vector<Obstacle> obstacles) {
  Problem p = problem;
  p.obstacles = std::move(obstacles);
  return p;
}

/// Makes each descriptor of `problem` smaller a cell at a time while `judge` allows; true when any changed.
bool shrinkSizes(Problem* problem, Judge& judge) {
  bool changed = false;
  for (std::size_t i = 0; i < problem->obstacles.size(); ++i) {
    for (bool smaller = true; smaller;) {
      smaller = false;
      for (const Obstacle& candidate : smallerObstacles(problem->obstacles[i])) {
        if (candidate.x >= problem->width || candidate.y < 0) continue;  // the anchor moved off the grid
        Problem p = *problem;
        p.obstacles[i] = candidate;
        if (judge(p)) {
          *problem = std::move(p);
          smaller = changed = true;
          break;
        }
      }
    }
  }
  return changed;
}

Problem shrinkDescriptors(const Problem& problem, Judge& judge) {
  const std::function<bool(const std::vector<Obstacle>&)> holds = [&](const std::vector<Obstacle>& kept) {
    return judge(withObstacles(problem, kept));
  };
  Problem shrunk = withObstacles(problem, removeWhilePossible(problem.obstacles, holds));
  // A smaller descriptor may let another go: repeat until neither step changes anything.
  while (shrinkSizes(&shrunk, judge)) {
    const std::size_t before = shrunk.obstacles.size();
    shrunk.obstacles = removeWhilePossible(shrunk.obstacles, holds);
    if (shrunk.obstacles.size() == before) break;
  }
  return shrunk;
}

/// The PPP whose obstacles are exactly `cells` (problemFromGrid), with `problem`'s metadata.
Problem fromCells(const Problem& problem, const std::vector<Cell>& cells) {
  Grid grid(problem.width, problem.height);
  for (const Cell c : cells) grid.setObstacle(c, true);
  Problem p = problemFromGrid(grid, problem.start, problem.goal);
  p.metadata = problem.metadata;
  return p;
}

/// The 4-connected components of the obstacle cells of `grid`, each in row-major order, ordered by their first
/// cell.
std::vector<std::vector<Cell>> obstacleComponents(const Grid& grid) {
  std::vector<int> label(static_cast<std::size_t>(grid.size()), -1);
  std::vector<std::vector<Cell>> components;
  for (int i = 0; i < grid.size(); ++i) {
    const Cell first = grid.cellAt(i);
    if (!grid.isObstacle(first) || label[static_cast<std::size_t>(i)] >= 0) continue;
    std::vector<Cell> component;
    std::vector<Cell> open = {first};
    label[static_cast<std::size_t>(i)] = static_cast<int>(components.size());
    while (!open.empty()) {
      const Cell c = open.back();
      open.pop_back();
      component.push_back(c);
      for (const Cell d : {Cell{1, 0}, Cell{-1, 0}, Cell{0, 1}, Cell{0, -1}}) {
        const Cell n{c.x + d.x, c.y + d.y};
        if (!grid.contains(n) || !grid.isObstacle(n) || label[static_cast<std::size_t>(grid.index(n))] >= 0) continue;
        label[static_cast<std::size_t>(grid.index(n))] = static_cast<int>(components.size());
        open.push_back(n);
      }
    }
    std::sort(component.begin(), component.end(), [&](Cell a, Cell b) { return grid.index(a) < grid.index(b); });
    components.push_back(std::move(component));
  }
  return components;
}

Problem shrinkCells(const Problem& problem, Judge& judge) {
  using Component = std::vector<Cell>;
  const auto flatten = [](const std::vector<Component>& components) {
    std::vector<Cell> cells;
    for (const Component& c : components) cells.insert(cells.end(), c.begin(), c.end());
    return cells;
  };
  const std::vector<Component> components = removeWhilePossible<Component>(
      obstacleComponents(decodeGrid(problem)),
      [&](const std::vector<Component>& kept) { return judge(fromCells(problem, flatten(kept))); });
  const std::vector<Cell> cells = removeWhilePossible<Cell>(
      flatten(components), [&](const std::vector<Cell>& kept) { return judge(fromCells(problem, kept)); });
  return fromCells(problem, cells);
}

}  // namespace

std::vector<Obstacle> smallerObstacles(const Obstacle& o) {
  std::vector<Obstacle> smaller;
  const auto add = [&](int dx, int dy, int dlength, int dheight) {
    Obstacle s = o;
    s.x += dx;
    s.y += dy;
    s.length += dlength;
    s.height += dheight;
    smaller.push_back(s);
  };
  if (o.length > 1) {
    add(0, 0, -1, 0);  // the far end
    switch (o.shape) {  // the anchor's end: the anchor moves one cell along
      case Shape::HorizontalBar: add(1, 0, -1, 0); break;
      case Shape::VerticalBar: add(0, 1, -1, 0); break;
      case Shape::DiagonalDown: add(1, 1, -1, 0); break;
      case Shape::DiagonalUp: add(1, -1, -1, 0); break;
      case Shape::Block: add(1, 0, -1, 0); break;
    }
  }
  if (o.shape == Shape::Block && o.height > 1) {
    add(0, 0, 0, -1);
    add(0, 1, 0, -1);
  }
  return smaller;
}

ShrinkResult shrinkProblem(const Problem& problem, const StillFails& still_fails, ShrinkUnits units,
                           const StopCheck& stop) {
  Judge judge(still_fails, stop);
  if (!judge(problem)) throw InvalidArgument("problem", "it does not fail as required to begin with: nothing to shrink");
  ShrinkResult result;
  result.problem = units == ShrinkUnits::Descriptors ? shrinkDescriptors(problem, judge) : shrinkCells(problem, judge);
  result.evaluations = judge.evaluations();
  return result;
}

}  // namespace ppp
