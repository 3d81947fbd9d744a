#pragma once

#include "ppp_agents/agent.hpp"
#include "ppp_agents/agent_memory.hpp"
#include "ppp_agents/navigation.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace agents {

/// `wall_follower_left` / `wall_follower_right`: keeps a wall (an obstacle or the map edge, as the scan reports
/// the four neighbours) on one side with the hand-on-wall rule: with an internal heading, it turns towards the
/// wall side if it can, else goes straight, else turns away, else turns back. Before touching any wall it heads
/// for the goal, each step along the axis with the larger distance left (a staircase along the diagonal from a
/// corner), until that move is blocked (or, with a random wall start, straight on in a heading drawn from its
/// seed); then it turns so the wall is on its side and never lets go of it. With `wall_leave: goal_free` it lets
/// go as soon as its move towards the goal is free (Bug0), heads for the goal again and follows the next wall it
/// meets: a concave pocket facing the goal then traps it, one hand more often than the other.
/// Fault: the first obstacle met from the default corner start is usually an island (a free-standing cycle of
/// walls); it circles it forever when the goal is not in sight from that loop.
/// With `wall_sense: touch` it reads no wall from its scan: each step it tries the move the rule prefers (towards
/// the wall side first) and, when that bumps, the next one in the rule's order, so along a straight wall it bumps
/// once per cell; it starts following a wall when its move before touching one (towards the goal, or straight on
/// after a random start) bumps.
/// Once it notices the goal it leaves the wall and takes a shortest path on its memory (kept for this alone), unless
/// its behaviour has goal seeking off.
class WallFollowerAgent final : public Agent {
 public:
  /// Which hand stays on the wall.
  enum class Side { Left, Right };
  /// A follower keeping the wall on `side`, with the behaviour's memory window for the goal.
  WallFollowerAgent(Side side, const AgentBehaviour& behaviour);
  /// Forgets the map and the wall; sets the initial heading towards the goal.
  void reset(const EpisodeInfo& info) override;
  /// One step of the hand-on-wall rule, or towards the goal once seen.
  Action act(const Scan& scan) override;

 private:
  /// The quarter-turn heading (index into kMoves) along the larger axis distance from `from` to `goal`; on a tie
  /// the horizontal one, or with random goal ties either, drawn from the episode's seed.
  int headingTowards(Cell from, Cell goal);
  /// The hand-on-wall rule by touch (wall_sense: touch), with `towards_goal` this step's heading for the goal.
  Action feel(const Scan& scan, int towards_goal);
  /// Quarter turns clockwise that turn away from the wall side: 1 for the left hand, 3 for the right.
  int awayFromWall() const { return side_ == Side::Left ? 1 : 3; }
  /// The heading of the hand-on-wall rule's move of rank 0 to 3 from heading_: towards the wall side, straight
  /// on, away from it, back.
  int ruleMove(int rank) const;

  Side side_;
  AgentBehaviour behaviour_;
  AgentMemory memory_;
  Navigator navigator_;
  bool goal_seen_ = false;
  bool engaged_ = false;  // touched a wall: the hand-on-wall rule is in force
  bool left_a_wall_ = false;  // let go of a wall (wall_leave): heads for the goal, even after a random start
  int heading_ = 0;       // index into kMoves
  int tried_ = -1;        // by touch: the heading of its last move, -1 when it was not the rule's (or none)
  int probe_ = 0;         // by touch: which of the rule's moves from heading_ it tries (0: towards the wall)
  Cell goal_;
  Rng rng_{0};
};

}  // namespace agents
}  // namespace ppp
