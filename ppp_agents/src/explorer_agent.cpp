#include "ppp_agents/explorer_agent.hpp"

#include <algorithm>
#include <cstdlib>

#include "ppp_core/visibility.hpp"

namespace ppp {
namespace agents {

ExplorerAgent::ExplorerAgent(bool long_term, int memory_window)
    : long_term_(long_term), memory_window_(memory_window) {}

void ExplorerAgent::reset(const EpisodeInfo& info) {
  memory_.reset(info.width, info.height, memory_window_);
  navigator_.reset(info.width, info.height);
  rng_ = Rng(info.seed);
  goal_seen_ = false;
  path_.clear();
  path_next_ = 0;
}

namespace {

/// Builds the line-of-sight table of one sensor range.
ExplorerAgent::SightTable buildSightTable(int range) {
  ExplorerAgent::SightTable table;
  table.range = range;
  for (int dy = -range; dy <= range; ++dy) {
    for (int dx = -range; dx <= range; ++dx) {
      table.begin.push_back(static_cast<int>(table.blockers.size()));
      for (Cell c : cellsCrossed(Cell{0, 0}, Cell{dx, dy})) table.blockers.push_back(c);
    }
  }
  table.begin.push_back(static_cast<int>(table.blockers.size()));
  return table;
}

}  // namespace

const ExplorerAgent::SightTable& ExplorerAgent::sightTable(int range) {
  // One table per range, shared by every explorer: an agent process hosting hundreds of episodes keeps one
  // copy hot in cache instead of hundreds cold ones.
  static const std::vector<SightTable> tables = [] {
    std::vector<SightTable> all;
    for (int r = 0; r <= kMaxSensorRange; ++r) all.push_back(buildSightTable(r));
    return all;
  }();
  return tables.at(static_cast<std::size_t>(range));
}

void ExplorerAgent::prefetch(Cell position) const {
  if (sight_ == nullptr) return;
  memory_.prefetch(position, sight_->range + 1);
  __builtin_prefetch(&unknown_count_);
  __builtin_prefetch(unknown_.data());
}

void ExplorerAgent::collectUnknown(Cell position, int range) {
  unknown_count_ = 0;
  const int reach = range + 1;
  const int y0 = std::max(position.y - reach, 0);
  const int y1 = std::min(position.y + reach, memory_.height() - 1);
  const int x0 = std::max(position.x - reach, 0);
  const int x1 = std::min(position.x + reach, memory_.width() - 1);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      if (memory_.isUnknown(Cell{x, y})) unknown_[unknown_count_++] = Cell{x, y};
    }
  }
}

int ExplorerAgent::unknownAround(Cell centre) const {
  const int range = sight_->range;
  const int side = 2 * range + 1;
  int count = 0;
  for (int u = 0; u < unknown_count_; ++u) {
    const int dx = unknown_[u].x - centre.x;
    const int dy = unknown_[u].y - centre.y;
    if (dx < -range || dx > range || dy < -range || dy > range) continue;
    const int i = (dy + range) * side + (dx + range);
    bool hidden = false;
    for (int b = sight_->begin[i]; b < sight_->begin[i + 1] && !hidden; ++b) {
      const Cell blocker = sight_->blockers[b];
      hidden = memory_.at(Cell{centre.x + blocker.x, centre.y + blocker.y}) == kScanObstacle;
    }
    count += hidden ? 0 : 1;
  }
  return count;
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
    valid = std::abs(next.x - position.x) + std::abs(next.y - position.y) == 1;
    for (std::size_t i = path_next_; valid && i < path_.size(); ++i) valid = memory_.isFree(path_[i]);
  }
  if (!valid) {
    const int found = navigator_.search(
        position, [&](Cell c) { return memory_.isFree(c); }, [&](Cell c) { return isFrontier(c); });
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
  Action action;
  if (navigator_.towardsSeenGoal(scan, memory_, &goal_seen_, &action)) return action;
  if (sight_ == nullptr || scan.range() != sight_->range) sight_ = &sightTable(scan.range());
  collectUnknown(position, sight_->range);
  Action best[4];
  int best_count = 0;
  int best_gain = 0;
  Action free[4];
  int free_count = 0;
  for (Action move : kMoves) {
    const Cell n = target(position, move);
    if (!memory_.isFree(n)) continue;
    free[free_count++] = move;
    const int gain = unknown_count_ > 0 ? unknownAround(n) : 0;
    if (gain > best_gain) {
      best_gain = gain;
      best_count = 0;
    }
    if (gain == best_gain && gain > 0) best[best_count++] = move;
  }
  if (best_count > 0) {
    path_.clear();
    path_next_ = 0;
    return best[best_count == 1 ? 0 : rng_.below(static_cast<std::uint64_t>(best_count))];
  }
  if (long_term_ && frontierStep(position, &action)) return action;
  if (free_count > 0) return free[free_count == 1 ? 0 : rng_.below(static_cast<std::uint64_t>(free_count))];
  return kMoves[rng_.below(4)];
}

}  // namespace agents
}  // namespace ppp
