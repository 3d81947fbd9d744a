#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "ppp_core/action.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {
namespace agents {

/// What an agent is told when an episode starts. Like a robot given a navigation goal, it knows its start,
/// the goal and the size of the area, never the map (the prior map is given only to agents that plan on it).
struct EpisodeInfo {
  int width = 0;                    ///< Map columns.
  int height = 0;                   ///< Map rows.
  Cell start;                       ///< Start cell.
  Cell goal;                        ///< Goal cell.
  std::uint64_t seed = 0;           ///< Seed of the agent's own random choices in this episode.
  const Grid* prior_map = nullptr;  ///< The true map, for agents with prior knowledge (astar); else null.
  Connectivity connectivity = Connectivity::Four;  ///< Move model; only astar takes diagonal moves under Eight.
};

/// How a built-in agent plays besides its type: the options of its configuration it reads (AgentConfig names them).
struct AgentBehaviour {
  int memory_window = 0;  ///< Limited memory: only a k x k window around the agent is kept (odd k); 0 = full.
  int memory_scans = 0;   ///< Limited memory: only what the last n scans saw is kept; 0 = every scan's.
  bool seek_goal = true;  ///< Once it has noticed the goal it takes a shortest path to it on its memory.
  int goal_range = 0;  ///< Notices the goal within this many cells (Chebyshev), walls or not; 0 = seen in the scan.
  bool random_wall_start = false;  ///< Wall followers: first straight on in a random heading, not towards the goal.
  bool leave_wall_for_goal = false;  ///< Wall followers: let go of the wall when the move towards the goal is free.
  bool random_goal_ties = false;  ///< Wall followers: as far from the goal across as down, either way at random.
  bool walls_by_touch = false;  ///< Wall followers: find the wall by bumping into it, not from the scan.
  bool quarter_turns = false;  ///< Bumpers: after a bump, turn left or right, never straight back.
  bool goal_ties_for_gain = false;  ///< Explorers: of neighbours revealing as much, those nearest the goal.
  bool idle_least_visited = false; ///< Explorers: with nothing new in reach, to the least visited free neighbour.
  bool frontier_towards_goal = false;  ///< Long-term explorer: the frontier least far to walk to plus on to the goal.
};

/// A test agent: each step it gets a scan (its cell, the goal, a bump flag and the window of cells) and returns
/// an action. One instance runs one episode at a time; reset() starts the next.
class Agent {
 public:
  virtual ~Agent() = default;
  /// Forgets everything and prepares for a new episode.
  virtual void reset(const EpisodeInfo& info) = 0;
  /// The action for this step.
  virtual Action act(const Scan& scan) = 0;
  /// Asks the processor to fetch what act() at `position` will read; a host acting on many agents in turn
  /// calls it a few agents ahead. Only a hint: does nothing by default.
  virtual void prefetch(Cell position) const { (void)position; }
};

}  // namespace agents
}  // namespace ppp
