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
  // Turns are free, so this is a breadth-first search over cells. Each cell is queued at most once, so the
  // queue is sized up front and the relaxations are branch-free (see fewestStateCost).
  cell_distance_.assign(free_.size(), kUnreached);
  if (current_.size() < free_.size()) current_.resize(free_.size());
  int* queue = current_.data();
  std::size_t tail = 0;
  queue[tail++] = start;
  cell_distance_[start] = 0;
  const int offsets[4] = {-padded_width_, 1, padded_width_, -1};
  for (std::size_t head = 0; head < tail; ++head) {
    const int cell = queue[head];
    const int d = cell_distance_[cell];
    if (cell == goal) return d;
    for (int offset : offsets) {
      const int n = cell + offset;
      const bool better = free_[n] && cell_distance_[n] == kUnreached;
      cell_distance_[n] = better ? d + 1 : cell_distance_[n];
      queue[tail] = n;
      tail += better ? 1 : 0;
    }
  }
  return -1;
}

int DpaSolver::fewestStateCost(int start, int goal, bool turn_costs, std::vector<int>* distance) {
  // Layered breadth-first search over states (cell * 4 + heading). With turn_costs only turns cost one and
  // advancing is free (fewest turns); otherwise both cost one (fewest turns + advances).
  // The relaxations are branch-free, as their branches were unpredictable and dominated the run time: a
  // successor is always written to the next free queue slot, and the slot is kept only when it improved.
  // current_ and next_ are buffers that only grow; their used lengths are tracked here.
  std::vector<int>& dist = *distance;
  dist.assign(free_.size() * 4, kUnreached);
  const int ahead[4] = {-padded_width_ * 4, 4, padded_width_ * 4, -4};  // state offset of the cell ahead
  if (current_.size() < 4) current_.resize(4);
  std::size_t current_size = 0;
  for (int h = 0; h < 4; ++h) {
    dist[start * 4 + h] = 0;
    current_[current_size++] = start * 4 + h;
  }
  for (int layer = 0; current_size > 0; ++layer) {
    const int next_layer = layer + 1;
    std::size_t queued = 0;
    auto relax = [&](int successor, bool open) {
      const bool better = open && dist[successor] > next_layer;
      dist[successor] = better ? next_layer : dist[successor];
      next_[queued] = successor;
      queued += better ? 1 : 0;
    };
    auto turnOff = [&](int state) {
      relax((state & ~3) | ((state + 3) & 3), true);
      relax((state & ~3) | ((state + 1) & 3), true);
    };
    if (turn_costs) {
      for (std::size_t head = 0; head < current_size; ++head) {
        int state = current_[head];
        if (dist[state] != layer) continue;  // improved after it was queued
        // Advancing is free: walk the whole ray ahead within this layer, turning off it at every cell, instead
        // of queueing each ray state and coming back to it (same distances, about half the memory traffic).
        for (;;) {
          if (next_.size() < queued + 2) next_.resize(2 * (queued + 2));
          turnOff(state);
          const int advanced = state + ahead[state & 3];
          if (!free_[advanced >> 2] || dist[advanced] <= layer) break;
          dist[advanced] = layer;
          state = advanced;
        }
      }
    } else {
      // Uniform costs: a state's first distance is final, so nothing queued goes stale.
      if (next_.size() < 3 * current_size) next_.resize(3 * current_size);
      for (std::size_t head = 0; head < current_size; ++head) {
        const int state = current_[head];
        const int advanced = state + ahead[state & 3];
        relax(advanced, free_[advanced >> 2] != 0);
        turnOff(state);
      }
    }
    const int best = std::min({dist[goal * 4], dist[goal * 4 + 1], dist[goal * 4 + 2], dist[goal * 4 + 3]});
    if (best <= layer) return best;
    current_.swap(next_);
    current_size = queued;
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
