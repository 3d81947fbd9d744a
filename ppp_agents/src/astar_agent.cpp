#include "ppp_agents/astar_agent.hpp"

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/octile.hpp"

namespace ppp {
namespace agents {

AstarAgent::AstarAgent(const AgentBehaviour& /*behaviour*/) {}

void AstarAgent::reset(const EpisodeInfo& info) {
  if (info.prior_map == nullptr) throw InvalidArgument("prior_map", "the astar agent needs the prior map");
  if (info.prior_map->width() != info.width || info.prior_map->height() != info.height) {
    throw InvalidArgument("prior_map", "expected a " + std::to_string(info.width) + "x" +
                                           std::to_string(info.height) + " map, got " +
                                           std::to_string(info.prior_map->width()) + "x" +
                                           std::to_string(info.prior_map->height()));
  }
  map_ = info.prior_map;
  own_map_ = false;
  connectivity_ = info.connectivity;
  goal_ = info.goal;
  plan(*map_, info.start, goal_, &plan_);
  next_ = 0;
  expected_ = info.start;
}

Action AstarAgent::act(const Scan& scan) {
  const Cell position = scan.position();
  if (scan.bumped() && map_->contains(expected_) && expected_ != goal_) {
    // The prior map was wrong: learn the obstacle in a copy of it (made on the first bump only).
    if (!own_map_) {
      corrected_ = *map_;
      map_ = &corrected_;
      own_map_ = true;
    }
    corrected_.setObstacle(expected_, true);
  }
  if (scan.bumped() || position != expected_ || next_ >= plan_.size()) {
    plan(*map_, position, goal_, &plan_);
    next_ = 0;
  }
  if (next_ >= plan_.size()) {
    expected_ = position;
    return Action::Stay;
  }
  const Action action = plan_[next_++];
  expected_ = target(position, action);
  return action;
}

bool AstarAgent::plan(const Grid& grid, Cell from, Cell goal, std::vector<Action>* plan) {
  plan->clear();
  if (!grid.isFree(from) || !grid.isFree(goal)) return false;
  if (from == goal) return true;
  if (connectivity_ == Connectivity::Eight) {  // octile-optimal: 1 per straight move, sqrt(2) per diagonal, no corner cut
    const OctileRoute route = shortestOctileRoute(grid, from, goal);
    for (std::size_t i = 1; i < route.cells.size(); ++i) {
      plan->push_back(actionTowards(route.cells[i - 1], route.cells[i]));
    }
    return route.length >= 0;
  }
  const auto cells = static_cast<std::size_t>(grid.size());
  g_.assign(cells, INT_MAX);
  parent_.assign(cells, -1);
  closed_.assign(cells, 0);
  open_.clear();
  const auto heuristic = [&](Cell c) { return manhattanDistance(c, goal); };
  // std::push_heap keeps the largest on top, so "worse" orders the best entry last.
  const auto worse = [](const Entry& a, const Entry& b) {
    if (a.f != b.f) return a.f > b.f;
    if (a.h != b.h) return a.h > b.h;
    return a.index > b.index;
  };
  const int start = grid.index(from);
  const int target_index = grid.index(goal);
  g_[start] = 0;
  open_.push_back(Entry{heuristic(from), heuristic(from), start});
  bool found = false;
  while (!open_.empty()) {
    std::pop_heap(open_.begin(), open_.end(), worse);
    const Entry e = open_.back();
    open_.pop_back();
    if (closed_[e.index]) continue;
    closed_[e.index] = 1;
    if (e.index == target_index) {
      found = true;
      break;
    }
    const Cell c = grid.cellAt(e.index);
    for (Action move : kMoves) {
      const Cell n = target(c, move);
      if (!grid.isFree(n)) continue;
      const int j = grid.index(n);
      if (closed_[j]) continue;
      const int g = g_[e.index] + 1;
      if (g >= g_[j]) continue;
      g_[j] = g;
      parent_[j] = e.index;
      const int h = heuristic(n);
      open_.push_back(Entry{g + h, h, j});
      std::push_heap(open_.begin(), open_.end(), worse);
    }
  }
  if (!found) return false;
  for (int i = target_index; parent_[i] >= 0; i = parent_[i]) {
    plan->push_back(actionTowards(grid.cellAt(parent_[i]), grid.cellAt(i)));
  }
  std::reverse(plan->begin(), plan->end());
  return true;
}

}  // namespace agents
}  // namespace ppp
