#pragma once

#include <cstdint>
#include <vector>

#include "ppp_agents/agent.hpp"
#include "ppp_core/grid.hpp"

namespace ppp {
namespace agents {

/// `astar`, the control: plans once with A* (Manhattan heuristic, deterministic tie-breaking) on the prior map
/// from start to goal and follows the plan, so on a valid PPP it passes in exactly the fewest moves. It reads
/// only the scan's position and bump flag; if it ever bumps or finds itself off the plan (impossible with a
/// correct prior map) it marks the cell it bumped into as an obstacle in its own copy of the map and plans again
/// from where it is. With no path it stays put. Under connectivity 8 it plans octile-optimal routes with diagonal
/// moves (shortestOctileRoute), the only built-in agent that takes them.
class AstarAgent final : public Agent {
 public:
  /// The behaviour is accepted for uniformity and unused: the prior map is the agent's knowledge.
  explicit AstarAgent(const AgentBehaviour& behaviour = {});
  /// Plans from the start. @throws InvalidArgument("prior_map", ...) when the info carries no prior map or
  /// one of another size.
  void reset(const EpisodeInfo& info) override;
  /// The next move of the plan.
  Action act(const Scan& scan) override;

  /// A* from `from` to `goal` on `grid`: writes the moves of a shortest path (4-connected, or octile under
  /// connectivity 8) into `plan` (empty when the goal is unreachable or equals `from`); returns whether a path
  /// exists.
  bool plan(const Grid& grid, Cell from, Cell goal, std::vector<Action>* plan);

 private:
  /// An open-list entry: ordered by f = g + h, then by h (deeper first), then by cell index.
  struct Entry {
    int f;
    int h;
    int index;
  };

  const Grid* map_ = nullptr;  // the prior map, or corrected_ after a bump
  Connectivity connectivity_ = Connectivity::Four;  // Eight plans octile-optimal routes with diagonal moves
  Grid corrected_;
  bool own_map_ = false;
  Cell goal_;
  Cell expected_;
  std::vector<Action> plan_;
  std::size_t next_ = 0;
  std::vector<int> g_;
  std::vector<int> parent_;
  std::vector<std::uint8_t> closed_;
  std::vector<Entry> open_;
};

}  // namespace agents
}  // namespace ppp
