#pragma once

// Benchmark maps for ppp_core, built reproducibly from fixed seeds with ppp::randomProblem / randomObstacle.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "ppp_core/grid.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/reachability.hpp"
#include "ppp_core/rng.hpp"

namespace ppp::bench {

/// Seed of the 20x20 map.
constexpr std::uint64_t kSmallMapSeed = 20;
/// Seed of the cluttered maps (200x200 and 1000x1000); the side is mixed in with deriveSeed.
constexpr std::uint64_t kClutteredMapSeed = 1000;
/// Descriptors in the 20x20 map.
constexpr int kSmallMapObstacles = 10;
/// Fraction of cells the cluttered maps cover with obstacles.
constexpr double kClutteredDensity = 0.22;
/// Size limits of the cluttered maps' descriptors: bars up to 60 cells, blocks up to 15x15.
inline const RandomObstacleOptions kClutteredOptions{60, 15};
/// Distance in cells around a new descriptor within which the free cells must stay connected to each other.
constexpr int kClutteredMargin = 4;

/// A solvable 20x20 PPP with 10 random descriptors (default size limits), drawn by randomProblem.
inline Problem smallMap() {
  Rng rng(kSmallMapSeed);
  return randomProblem(rng, Problem::empty(20, 20, kSmallMapObstacles), kSmallMapObstacles);
}

/// True when every free cell of `grid` inside the window [x0, x1] x [y0, y1] is 4-connected to every other
/// one without leaving the window. `queue` and `seen` are scratch buffers.
inline bool windowConnected(const Grid& grid, int x0, int y0, int x1, int y1, std::vector<int>* queue,
                            std::vector<std::uint8_t>* seen) {
  const int w = x1 - x0 + 1;
  const int h = y1 - y0 + 1;
  seen->assign(static_cast<std::size_t>(w) * h, 0);
  queue->clear();
  int free_cells = 0;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      if (grid.isObstacle(Cell{x, y})) continue;
      if (free_cells++ == 0) {
        queue->push_back((y - y0) * w + (x - x0));
        (*seen)[queue->back()] = 1;
      }
    }
  }
  for (std::size_t head = 0; head < queue->size(); ++head) {
    const int i = (*queue)[head];
    const int x = i % w;
    const int y = i / w;
    const int next[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
    for (const auto& n : next) {
      if (n[0] < 0 || n[1] < 0 || n[0] >= w || n[1] >= h) continue;
      const int j = n[1] * w + n[0];
      if ((*seen)[j] || grid.isObstacle(Cell{x0 + n[0], y0 + n[1]})) continue;
      (*seen)[j] = 1;
      queue->push_back(j);
    }
  }
  return static_cast<int>(queue->size()) == free_cells;
}

/// A solvable side x side PPP whose random descriptors cover kClutteredDensity of the grid.
/// Plain randomProblem draws at that density are practically never solvable (diagonal bars are walls for
/// 4-connected moves, so the free space falls apart into pockets), so descriptors drawn by randomObstacle
/// are kept only when the free cells within kClutteredMargin of them stay connected locally. By induction
/// every free cell stays reachable from every other: the start's region is the whole free space (the
/// expensive case for DPA). Start, goal and centre are never covered. @throws std::runtime_error if the
/// density is not reached or the goal is unreachable.
inline Problem clutteredMap(int side) {
  Rng rng(deriveSeed(kClutteredMapSeed, {static_cast<std::uint64_t>(side)}));
  Problem problem = Problem::empty(side, side, 0);
  const Cell centre{side / 2, side / 2};
  Grid painted(side, side);
  std::vector<int> queue;
  std::vector<std::uint8_t> seen;
  std::vector<Cell> added;
  const auto target = static_cast<int>(kClutteredDensity * side * side);
  int covered = 0;
  for (int draw = 0; covered < target; ++draw) {
    if (draw >= 1000 * side) throw std::runtime_error("clutteredMap: density not reached");
    const Obstacle o = randomObstacle(rng, side, side, kClutteredOptions);
    const auto cells = obstacleCells(o, side, side);
    if (std::find(cells.begin(), cells.end(), problem.start) != cells.end() ||
        std::find(cells.begin(), cells.end(), problem.goal) != cells.end() ||
        std::find(cells.begin(), cells.end(), centre) != cells.end()) {
      continue;
    }
    added.clear();
    int x0 = side, y0 = side, x1 = -1, y1 = -1;
    for (Cell c : cells) {
      if (painted.isObstacle(c)) continue;
      painted.setObstacle(c, true);
      added.push_back(c);
      x0 = std::min(x0, c.x);
      y0 = std::min(y0, c.y);
      x1 = std::max(x1, c.x);
      y1 = std::max(y1, c.y);
    }
    if (added.empty()) continue;
    if (!windowConnected(painted, std::max(0, x0 - kClutteredMargin), std::max(0, y0 - kClutteredMargin),
                         std::min(side - 1, x1 + kClutteredMargin), std::min(side - 1, y1 + kClutteredMargin),
                         &queue, &seen)) {
      for (Cell c : added) painted.setObstacle(c, false);
      continue;
    }
    covered += static_cast<int>(added.size());
    problem.obstacles.push_back(o);
  }
  problem.max_obstacles = static_cast<int>(problem.obstacles.size());
  validateProblem(problem);
  if (!isReachable(decodeGrid(problem), problem.start, problem.goal)) {
    throw std::runtime_error("clutteredMap: goal unreachable");
  }
  return problem;
}

/// The benchmark map with the given side: 20 is smallMap(), any other side clutteredMap(side). Built once.
inline const Problem& benchProblem(int side) {
  static std::map<int, Problem> cache;
  auto it = cache.find(side);
  if (it == cache.end()) it = cache.emplace(side, side == 20 ? smallMap() : clutteredMap(side)).first;
  return it->second;
}

/// The decoded grid of benchProblem(side). Built once.
inline const Grid& benchGrid(int side) {
  static std::map<int, Grid> cache;
  auto it = cache.find(side);
  if (it == cache.end()) it = cache.emplace(side, decodeGrid(benchProblem(side))).first;
  return it->second;
}

/// The centre viewpoint (width/2, height/2), as Evaluator uses it.
inline Cell centreCell(const Problem& problem) { return Cell{problem.width / 2, problem.height / 2}; }

/// A label such as "1000x1000, 6812 descriptors, 25.0% obstacles" for a benchmark's report.
inline std::string describe(int side) {
  const Grid& grid = benchGrid(side);
  char percent[16];
  std::snprintf(percent, sizeof percent, "%.1f%%", 100.0 * grid.obstacleCount() / grid.size());
  return std::to_string(side) + "x" + std::to_string(side) + ", " +
         std::to_string(benchProblem(side).obstacles.size()) + " descriptors, " + percent + " obstacles";
}

}  // namespace ppp::bench
