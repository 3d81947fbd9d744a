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

/// True when the goal lies in the scan window and is reported free, i.e. the agent sees it in line of sight.
/// Reads the window only when the goal is within range.
inline bool goalSeen(const Scan& scan) {
  const Cell p = scan.position();
  const Cell g = scan.goal();
  const int r = scan.range();
  if (g.x < p.x - r || g.x > p.x + r || g.y < p.y - r || g.y > p.y + r) return false;
  return scan.at(g.x - p.x, g.y - p.y) == kScanFree;
}

/// True when the goal lies within the scan window (Chebyshev distance <= range); reads nothing.
inline bool goalInWindow(const Scan& scan) {
  const Cell p = scan.position();
  const Cell g = scan.goal();
  const int r = scan.range();
  return g.x >= p.x - r && g.x <= p.x + r && g.y >= p.y - r && g.y <= p.y + r;
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

  /// The first move of the path found to `target` by the last search().
  Action firstAction(int target) const { return static_cast<Action>(first_[target]); }

  /// Writes the cells of the path found to `target` by the last search() into `path`, from the first cell
  /// after the start to the target.
  void path(int target, std::vector<Cell>* path) const;

  /// First move of a shortest path from `from` to `goal` over cells not remembered as obstacles (unknown
  /// cells count as passable: the free-space assumption; the goal always does). Returns false when memory
  /// shows no such path.
  bool towardsGoal(const AgentMemory& memory, Cell from, Cell goal, Action* action);

  /// towardsGoal() from the scan's position once the goal has been seen: sets `*goal_seen` when this scan
  /// shows the goal (it stays set), and returns false while the goal is unseen or memory shows no path.
  bool towardsSeenGoal(const Scan& scan, const AgentMemory& memory, bool* goal_seen, Action* action);

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

}  // namespace agents
}  // namespace ppp
