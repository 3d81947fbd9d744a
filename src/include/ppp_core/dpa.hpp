#pragma once

#include <cstdint>
#include <vector>

#include "ppp_core/grid.hpp"

namespace ppp {

/// A robot heading on the grid (y down, so North is towards row 0).
enum class Heading : std::uint8_t { North = 0, East = 1, South = 2, West = 3 };

/// What Ashlock's dynamic-programming evaluation finds for one start/goal pair.
struct DpaResult {
  bool reachable = false;         ///< False when no route exists: the PPP is invalid and the counts are -1.
  int turns = -1;                 ///< Fewest 90-degree turns over all routes (start heading is free).
  int advances = -1;              ///< Fewest one-cell advances over all routes.
  int turns_plus_advances = -1;   ///< Fewest turns plus advances over all routes.
  std::vector<Cell> route;        ///< Cells of one route achieving turns_plus_advances, start to goal.
  Heading start_heading = Heading::North;  ///< The heading that route starts in.
};

/// Ashlock's evaluation over states (x, y, heading): turn left/right costs one turn, advancing one cell costs
/// one advance. Keeps its work buffers between calls, so reuse one solver for many problems.
class DpaSolver {
 public:
  /// Solves all three measures and the turns+advances route. Start and goal must be free cells on the grid.
  const DpaResult& solve(const Grid& grid, Cell start, Cell goal);

 private:
  void pad(const Grid& grid);
  int fewestAdvances(int start, int goal);
  int fewestStateCost(int start, int goal, bool turn_costs, std::vector<int>* distance);
  void traceRoute(int goal);

  int padded_width_ = 0;
  std::vector<std::uint8_t> free_;  // padded grid, obstacle border
  std::vector<int> cell_distance_;
  std::vector<int> turn_distance_;
  std::vector<int> step_distance_;
  std::vector<int> current_;
  std::vector<int> next_;
  DpaResult result_;
};

/// One-shot convenience: a fresh solver's answer.
DpaResult solveDpa(const Grid& grid, Cell start, Cell goal);

}  // namespace ppp
