#include "ppp_agents/explorer_agent.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>

#include "ppp_agents/reveal_counter.hpp"

namespace ppp {
namespace agents {

namespace {

/// Keeps, of the first `count` moves, those with the least `key(move)`, in order; returns how many.
template <class Key>
int keepLeast(Action* moves, int count, Key key) {
  auto least = key(moves[0]);
  for (int i = 1; i < count; ++i) least = std::min(least, key(moves[i]));
  int kept = 0;
  for (int i = 0; i < count; ++i) {
    if (key(moves[i]) == least) moves[kept++] = moves[i];
  }
  return kept;
}

}  // namespace

ExplorerAgent::ExplorerAgent(bool long_term, const AgentBehaviour& behaviour)
    : long_term_(long_term), behaviour_(behaviour) {}

void ExplorerAgent::reset(const EpisodeInfo& info) {
  memory_.reset(info.width, info.height, behaviour_.memory_window, behaviour_.memory_scans);
  navigator_.reset(info.width, info.height);
  rng_ = Rng(info.seed);
  goal_seen_ = false;
  goal_ = info.goal;
  width_ = info.width;
  if (behaviour_.idle_least_visited) {
    visits_.assign(static_cast<std::size_t>(info.width) * static_cast<std::size_t>(info.height), 0);
  }
  path_.clear();
  path_next_ = 0;
}

void ExplorerAgent::prefetch(Cell position) const {
  if (range_ > 0) memory_.prefetch(position, range_ + 1);
}

bool ExplorerAgent::isFrontier(Cell c) const {
  if (!memory_.isFree(c)) return false;
  for (Action move : kMoves) {
    if (memory_.isUnknown(target(c, move))) return true;
  }
  return false;
}

bool ExplorerAgent::frontierStep(Cell position, Action* action) {
  bool valid = path_next_ < path_.size() && isFrontier(path_.back());
  if (valid) {
    const Cell next = path_[path_next_];
    valid = manhattanDistance(next, position) == 1;
    for (std::size_t i = path_next_; valid && i < path_.size(); ++i) valid = memory_.isFree(path_[i]);
  }
  if (!valid) {
    const auto known_free = [&](Cell c) { return memory_.isFree(c); };
    const int found =
        behaviour_.frontier_towards_goal
            ? navigator_.searchLeast(position, known_free,
                                     [&](Cell c) { return isFrontier(c) ? manhattanDistance(c, goal_) : -1; })
            : navigator_.search(position, known_free, [&](Cell c) { return isFrontier(c); });
    if (found < 0) {
      path_.clear();
      path_next_ = 0;
      return false;
    }
    navigator_.path(found, &path_);
    path_next_ = 0;
  }
  const Cell next = path_[path_next_++];
  *action = next.x > position.x ? Action::East
            : next.x < position.x ? Action::West
            : next.y > position.y ? Action::South
                                  : Action::North;
  return true;
}

Action ExplorerAgent::act(const Scan& scan) {
  const Cell position = scan.position();
  memory_.update(scan);
  if (behaviour_.idle_least_visited) {
    std::uint16_t& visits = visits_[static_cast<std::size_t>(position.y) * width_ + position.x];
    if (visits < UINT16_MAX) ++visits;
  }
  Action action;
  if (behaviour_.seek_goal && navigator_.towardsSeenGoal(scan, memory_, behaviour_.goal_range, &goal_seen_, &action)) {
    return action;
  }
  range_ = scan.range();
  std::array<bool, 4> open{};
  for (int i = 0; i < 4; ++i) open[i] = memory_.isFree(target(position, kMoves[i]));
  std::array<int, 4> gains;
  revealGains(memory_, position, range_, open, &gains);
  Action best[4];
  int best_count = 0;
  int best_gain = 0;
  Action free[4];
  int free_count = 0;
  for (int i = 0; i < 4; ++i) {
    if (!open[i]) continue;
    free[free_count++] = kMoves[i];
    if (gains[i] > best_gain) {
      best_gain = gains[i];
      best_count = 0;
    }
    if (gains[i] == best_gain && gains[i] > 0) best[best_count++] = kMoves[i];
  }
  if (best_count > 1 && behaviour_.goal_ties_for_gain) {
    best_count = keepLeast(best, best_count,
                           [&](Action move) { return manhattanDistance(target(position, move), goal_); });
  }
  if (best_count > 0) {
    path_.clear();
    path_next_ = 0;
    return best[best_count == 1 ? 0 : rng_.below(static_cast<std::uint64_t>(best_count))];
  }
  if (long_term_ && frontierStep(position, &action)) return action;
  if (behaviour_.idle_least_visited && free_count > 1) {
    // Keep only the free neighbours stood on least often.
    free_count = keepLeast(free, free_count, [&](Action move) {
      const Cell c = target(position, move);
      return visits_[static_cast<std::size_t>(c.y) * width_ + c.x];
    });
  }
  if (free_count > 0) return free[free_count == 1 ? 0 : rng_.below(static_cast<std::uint64_t>(free_count))];
  return kMoves[rng_.below(4)];
}

}  // namespace agents
}  // namespace ppp
