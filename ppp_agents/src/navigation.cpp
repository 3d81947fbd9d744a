#include "ppp_agents/navigation.hpp"

#include <algorithm>

namespace ppp {
namespace agents {

void Navigator::reset(int width, int height) {
  width_ = width;
  height_ = height;
  const std::size_t cells = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (seen_.size() < cells) {
    seen_.assign(cells, 0u);
    parent_.assign(cells, -1);
    first_.assign(cells, 0);
    queue_.assign(cells, 0);
    steps_.assign(cells, 0);
    stamp_ = 0;
  }
}

void Navigator::path(int target, std::vector<Cell>* path) const {
  path->clear();
  for (int i = target; parent_[i] >= 0; i = parent_[i]) path->push_back(Cell{i % width_, i / width_});
  std::reverse(path->begin(), path->end());
}

bool Navigator::towardsGoal(const AgentMemory& memory, Cell from, Cell goal, Action* action) {
  const int found = search(
      from, [&](Cell c) { return c == goal || memory.at(c) != kScanObstacle; },
      [&](Cell c) { return c == goal; });
  if (found < 0) return false;
  *action = firstAction(found);
  return true;
}

bool Navigator::towardsSeenGoal(const Scan& scan, const AgentMemory& memory, int goal_range, bool* goal_seen,
                                Action* action) {
  if (!*goal_seen) *goal_seen = goalSeen(scan, goal_range);
  return *goal_seen && towardsGoal(memory, scan.position(), scan.goal(), action);
}

}  // namespace agents
}  // namespace ppp
