#pragma once

#include <cstdint>
#include <vector>

#include "ppp_agents/agent.hpp"
#include "ppp_agents/agent_memory.hpp"
#include "ppp_agents/navigation.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace agents {

/// `explorer` and `long_term_explorer`. Both remember what they see and, each step, move to the 4-neighbour
/// (free in memory) whose sensor window holds the most unknown cells that could be seen from it (cells behind
/// a remembered obstacle do not count: they stay hidden, and counting them would make the agent shuttle
/// between two cells forever), ties broken at random (with `explorer_ties: goal`, among the tied neighbours
/// nearest the goal by Manhattan distance: it knows where the goal is, as a robot given a navigation goal does).
/// - explorer: when no neighbour would reveal anything it moves to a random free neighbour (with `explorer_idle:
///   least_visited`, to one it has stood on least often, ties at random); fault: it wanders in explored areas.
/// - long_term_explorer: then it follows a shortest path on its memory (known-free cells) to the nearest
///   frontier (a known-free cell with an unknown 4-neighbour; with `frontier: goal`, the one with the least walk
///   to it plus Manhattan distance on to the goal), re-planning when a cell of the path turns out blocked or the
///   frontier is gone; fault: it may travel far for single unknown cells.
/// Once either has noticed the goal (seen free in its scan, or within its goal_range) it takes a shortest path to
/// it on its memory (unknown cells passable), unless its behaviour has goal seeking off.
class ExplorerAgent final : public Agent {
 public:
  /// An explorer; `long_term` selects the frontier-seeking variant.
  ExplorerAgent(bool long_term, const AgentBehaviour& behaviour);
  /// Forgets the map and reseeds the tie-breaking generator.
  void reset(const EpisodeInfo& info) override;
  /// One greedy (or frontier, or goal) step.
  Action act(const Scan& scan) override;
  /// Fetches the remembered cells around `position`.
  void prefetch(Cell position) const override;

 private:
  /// True when a cell is known free and has an unknown on-map 4-neighbour.
  bool isFrontier(Cell c) const;
  /// The next move along the frontier path (re-planned when needed), or false when there is no frontier.
  bool frontierStep(Cell position, Action* action);

  bool long_term_;
  AgentBehaviour behaviour_;
  AgentMemory memory_;
  Navigator navigator_;
  Rng rng_{0};
  bool goal_seen_ = false;
  Cell goal_;
  int width_ = 0;
  std::vector<std::uint16_t> visits_;  // with idle_least_visited: per cell, the steps the agent stood on it
  int range_ = 0;  // of the last scan; 0 before the first
  std::vector<Cell> path_;    // long_term: cells still to visit, the frontier last
  std::size_t path_next_ = 0;
};

}  // namespace agents
}  // namespace ppp
