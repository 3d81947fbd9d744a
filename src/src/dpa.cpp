#include "ppp_core/dpa.hpp"

#include <algorithm>
#include <limits>

namespace ppp {

namespace {

constexpr int kUnreached = std::numeric_limits<int>::max();

}  // namespace

void DpaSolver::pad(const Grid& grid) {
  padded_width_ = grid.width() + 2;
  const std::size_t padded_cells = static_cast<std::size_t>(padded_width_) * (grid.height() + 2);
  free_.assign(padded_cells, 0);
  const auto& cells = grid.cells();
  for (int y = 0; y < grid.height(); ++y) {
    const std::uint8_t* row = cells.data() + static_cast<std::size_t>(y) * grid.width();
    std::uint8_t* out = free_.data() + static_cast<std::size_t>(y + 1) * padded_width_ + 1;
    for (int x = 0; x < grid.width(); ++x) out[x] = row[x] == 0 ? 1 : 0;
  }
}

int DpaSolver::fewestAdvances(int start, int goal) {
  // Turns are free, so this is a breadth-first search over cells.
  cell_distance_.assign(free_.size(), kUnreached);
  current_.clear();
  current_.push_back(start);
  cell_distance_[start] = 0;
  const int offsets[4] = {-padded_width_, 1, padded_width_, -1};
  for (std::size_t head = 0; head < current_.size(); ++head) {
    const int cell = current_[head];
    const int d = cell_distance_[cell];
    if (cell == goal) return d;
    for (int offset : offsets) {
      const int n = cell + offset;
      if (free_[n] && cell_distance_[n] == kUnreached) {
        cell_distance_[n] = d + 1;
        current_.push_back(n);
      }
    }
  }
  return -1;
}

int DpaSolver::fewestStateCost(int start, int goal, bool turn_costs, std::vector<int>* distance) {
  // Layered breadth-first search over states (cell * 4 + heading). With turn_costs only turns cost one and
  // advancing is free (fewest turns); otherwise both cost one (fewest turns + advances).
  std::vector<int>& dist = *distance;
  dist.assign(free_.size() * 4, kUnreached);
  const int offsets[4] = {-padded_width_, 1, padded_width_, -1};
  current_.clear();
  next_.clear();
  for (int h = 0; h < 4; ++h) {
    dist[start * 4 + h] = 0;
    current_.push_back(start * 4 + h);
  }
  for (int layer = 0; !current_.empty(); ++layer) {
    for (std::size_t head = 0; head < current_.size(); ++head) {
      const int state = current_[head];
      if (dist[state] != layer) continue;  // improved after it was queued
      const int cell = state >> 2;
      const int h = state & 3;
      const int ahead = cell + offsets[h];
      if (free_[ahead]) {
        const int advanced = ahead * 4 + h;
        if (!turn_costs) {
          if (dist[advanced] > layer + 1) {
            dist[advanced] = layer + 1;
            next_.push_back(advanced);
          }
        } else if (dist[advanced] > layer) {
          dist[advanced] = layer;
          current_.push_back(advanced);
        }
      }
      const int left = cell * 4 + ((h + 3) & 3);
      const int right = cell * 4 + ((h + 1) & 3);
      if (dist[left] > layer + 1) {
        dist[left] = layer + 1;
        next_.push_back(left);
      }
      if (dist[right] > layer + 1) {
        dist[right] = layer + 1;
        next_.push_back(right);
      }
    }
    const int best = std::min({dist[goal * 4], dist[goal * 4 + 1], dist[goal * 4 + 2], dist[goal * 4 + 3]});
    if (best <= layer) return best;
    current_.swap(next_);
    next_.clear();
  }
  return -1;
}

void DpaSolver::traceRoute(int goal) {
  // Walk back from the best goal state along predecessors whose cost is exactly one less.
  const int offsets[4] = {-padded_width_, 1, padded_width_, -1};
  const std::vector<int>& dist = step_distance_;
  int state = goal * 4;
  for (int h = 1; h < 4; ++h) {
    if (dist[goal * 4 + h] < dist[state]) state = goal * 4 + h;
  }
  std::vector<int> cells{state >> 2};
  while (dist[state] > 0) {
    const int cell = state >> 2;
    const int h = state & 3;
    const int d = dist[state];
    const int behind = cell - offsets[h];
    if (free_[behind] && dist[behind * 4 + h] == d - 1) {
      state = behind * 4 + h;
      cells.push_back(behind);
    } else if (dist[cell * 4 + ((h + 1) & 3)] == d - 1) {
      state = cell * 4 + ((h + 1) & 3);
    } else {
      state = cell * 4 + ((h + 3) & 3);
    }
  }
  result_.start_heading = static_cast<Heading>(state & 3);
  result_.route.clear();
  for (auto it = cells.rbegin(); it != cells.rend(); ++it) {
    result_.route.push_back(Cell{*it % padded_width_ - 1, *it / padded_width_ - 1});
  }
}

const DpaResult& DpaSolver::solve(const Grid& grid, Cell start, Cell goal) {
  result_ = DpaResult{};
  if (!grid.isFree(start) || !grid.isFree(goal)) return result_;
  pad(grid);
  const int start_cell = (start.y + 1) * padded_width_ + start.x + 1;
  const int goal_cell = (goal.y + 1) * padded_width_ + goal.x + 1;
  result_.advances = fewestAdvances(start_cell, goal_cell);
  if (result_.advances < 0) return result_;
  result_.reachable = true;
  result_.turns = fewestStateCost(start_cell, goal_cell, true, &turn_distance_);
  result_.turns_plus_advances = fewestStateCost(start_cell, goal_cell, false, &step_distance_);
  traceRoute(goal_cell);
  return result_;
}

DpaResult solveDpa(const Grid& grid, Cell start, Cell goal) {
  DpaSolver solver;
  return solver.solve(grid, start, goal);
}

}  // namespace ppp
