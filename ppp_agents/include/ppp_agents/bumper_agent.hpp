#pragma once

#include <cstdint>
#include <vector>

#include "ppp_agents/agent.hpp"
#include "ppp_agents/agent_memory.hpp"
#include "ppp_agents/navigation.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace agents {

/// `bumper` and `decision_bumper`: go straight (first in a random direction) until a bump, then turn.
/// - bumper: the new direction is uniform among the three other than the one that bumped.
/// - decision_bumper: remembers, per cell where it bumped, the directions already tried there; it picks
///   uniformly among the untried ones and only when all four are exhausted among the three other than the
///   bumped one.
/// With `bumper_turn: quarter` both draw only among the two quarter turns (left or right of the bumped
/// direction), never straight back: the decision bumper among the untried ones of those two first.
/// Both steer by the bump flag alone: they read the scan window only while the goal is within the window or their
/// goal range (goalNearby()), remembering those scans; once the goal is noticed they take a shortest path to
/// it on that memory (unknown cells passable); with goal seeking off they never read it. Fault: straight lines
/// and random turns leave them trapped in
/// pockets whose exit they rarely line up with.
class BumperAgent final : public Agent {
 public:
  /// A bumper; `decision` selects the variant that remembers tried directions.
  BumperAgent(bool decision, const AgentBehaviour& behaviour);
  /// Forgets everything, reseeds and draws the first direction.
  void reset(const EpisodeInfo& info) override;
  /// Straight on, a new direction after a bump, or towards the goal once seen.
  Action act(const Scan& scan) override;

 private:
  /// Picks a new direction after `bumped` (index into kMoves) hit at `position`.
  int turn(Cell position, int bumped);

  bool decision_;
  AgentBehaviour behaviour_;
  int width_ = 0;
  AgentMemory memory_;
  Navigator navigator_;
  Rng rng_{0};
  bool goal_seen_ = false;
  int direction_ = 0;  // index into kMoves of the straight run
  int last_ = 0;       // index into kMoves of the last move, -1 after Stay
  std::vector<std::uint8_t> tried_;  // decision_bumper: per cell, bit d set when direction d was tried there
};

}  // namespace agents
}  // namespace ppp
