#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "ppp_core/action.hpp"
#include "ppp_agents/agent_memory.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {
namespace agents {

/// Whether the goal lies within `cells` of the agent (Chebyshev distance). Reads nothing.
inline bool goalWithin(const Scan& scan, int cells) {
  const Cell p = scan.position();
  const Cell g = scan.goal();
  return g.x >= p.x - cells && g.x <= p.x + cells && g.y >= p.y - cells && g.y <= p.y + cells;
}

/// True when the goal may be noticed from this scan: it lies within the scan window or within `goal_range` cells.
/// Reads nothing.
inline bool goalNearby(const Scan& scan, int goal_range) {
  return goalWithin(scan, std::max(scan.range(), goal_range));
}

/// True when the agent notices the goal: when it lies within `goal_range` cells, whatever lies between (the agent
/// knows both positions; 0: never so), or in the scan window reported free (it sees it in line of sight; the window
/// is read only then).
inline bool goalSeen(const Scan& scan, int goal_range) {
  if (goal_range > 0 && goalWithin(scan, goal_range)) return true;
  if (!goalWithin(scan, scan.range())) return false;
  return scan.at(scan.goal().x - scan.position().x, scan.goal().y - scan.position().y) == kScanFree;
}

/// Breadth-first search over a W x H grid of cells with reusable buffers (no allocation after reset()):
/// shortest 4-connected paths from the agent's cell to a target cell or to the nearest cell satisfying a
/// predicate. Neighbours are expanded in the order N, E, S, W, so results are deterministic.
class Navigator {
 public:
  /// Sizes the buffers for a map (allocates only when the map is larger than any before).
  void reset(int width, int height);

  /// Searches from `from` through cells with passable(cell) true (the start need not be) and returns the
  /// index (y * width + x) of the nearest cell other than `from` with is_target(cell) true, or -1.
  template <class Passable, class IsTarget>
  int search(Cell from, Passable passable, IsTarget is_target);

  /// Searches like search() and returns the index of the cell other than `from` with the least steps from `from`
  /// plus cost(cell), among cells with cost(cell) >= 0 (the others are no targets), the one found first on ties;
  /// -1 when there is none. Stops once no cell further out can do better.
  template <class Passable, class Cost>
  int searchLeast(Cell from, Passable passable, Cost cost);

  /// The first move of the path found to `target` by the last search() or searchLeast().
  Action firstAction(int target) const { return static_cast<Action>(first_[target]); }

  /// Writes the cells of the path found to `target` by the last search() or searchLeast() into `path`, from the
  /// first cell after the start to the target.
  void path(int target, std::vector<Cell>* path) const;

  /// First move of a shortest path from `from` to `goal` over cells not remembered as obstacles (unknown
  /// cells count as passable: the free-space assumption; the goal always does). Returns false when memory
  /// shows no such path.
  bool towardsGoal(const AgentMemory& memory, Cell from, Cell goal, Action* action);

  /// towardsGoal() from the scan's position once the goal has been noticed: sets `*goal_seen` when
  /// goalSeen(scan, goal_range) (it stays set), and returns false while the goal is unseen or memory shows no path.
  bool towardsSeenGoal(const Scan& scan, const AgentMemory& memory, int goal_range, bool* goal_seen, Action* action);

  /// Map columns the buffers are sized for.
  int width() const { return width_; }

 private:
  int width_ = 0;
  int height_ = 0;
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> seen_;
  std::vector<int> parent_;
  std::vector<std::uint8_t> first_;
  std::vector<int> queue_;
  std::vector<int> steps_;  // searchLeast(): steps from the start, per reached cell
};

template <class Passable, class IsTarget>
int Navigator::search(Cell from, Passable passable, IsTarget is_target) {
  if (++stamp_ == 0) {
    std::fill(seen_.begin(), seen_.end(), 0u);
    stamp_ = 1;
  }
  const int start = from.y * width_ + from.x;
  seen_[start] = stamp_;
  parent_[start] = -1;
  first_[start] = static_cast<std::uint8_t>(Action::Stay);
  int head = 0;
  int tail = 0;
  queue_[tail++] = start;
  while (head < tail) {
    const int i = queue_[head++];
    const Cell c{i % width_, i / width_};
    if (i != start && is_target(c)) return i;
    for (Action move : kMoves) {
      const Cell n = target(c, move);
      if (n.x < 0 || n.y < 0 || n.x >= width_ || n.y >= height_) continue;
      const int j = n.y * width_ + n.x;
      if (seen_[j] == stamp_ || !passable(n)) continue;
      seen_[j] = stamp_;
      parent_[j] = i;
      first_[j] = i == start ? static_cast<std::uint8_t>(move) : first_[i];
      queue_[tail++] = j;
    }
  }
  return -1;
}

template <class Passable, class Cost>
int Navigator::searchLeast(Cell from, Passable passable, Cost cost) {
  int best = -1;
  int best_score = 0;
  steps_[from.y * width_ + from.x] = 0;
  search(from, passable,
         [&](Cell c) {
           const int i = c.y * width_ + c.x;
           steps_[i] = steps_[parent_[i]] + 1;
           if (best >= 0 && steps_[i] >= best_score) return true;  // nothing further out can do better
           const int extra = cost(c);
           if (extra >= 0 && (best < 0 || steps_[i] + extra < best_score)) {
             best = i;
             best_score = steps_[i] + extra;
           }
           return false;
         });
  return best;
}

}  // namespace agents
}  // namespace ppp
