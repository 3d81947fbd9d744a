#include "ppp_agents/wall_follower_agent.hpp"

#include <algorithm>
#include <cstdlib>

namespace ppp {
namespace agents {

WallFollowerAgent::WallFollowerAgent(Side side, const AgentBehaviour& behaviour) : side_(side), behaviour_(behaviour) {}

void WallFollowerAgent::reset(const EpisodeInfo& info) {
  if (behaviour_.seek_goal) {
    memory_.reset(info.width, info.height, behaviour_.memory_window, behaviour_.memory_scans);
    navigator_.reset(info.width, info.height);
  }
  goal_seen_ = false;
  engaged_ = false;
  left_a_wall_ = false;
  tried_ = -1;
  probe_ = 0;
  goal_ = info.goal;
  rng_ = Rng(info.seed);
  heading_ = behaviour_.random_wall_start ? static_cast<int>(rng_.below(4)) : 0;  // else act() heads for the goal
}

int WallFollowerAgent::headingTowards(Cell from, Cell goal) {
  const int dx = goal.x - from.x;
  const int dy = goal.y - from.y;
  const int horizontal = dx >= 0 ? 1 : 3;  // East or West
  const int vertical = dy >= 0 ? 2 : 0;    // South or North
  if (std::abs(dx) == std::abs(dy) && dx != 0 && behaviour_.random_goal_ties) {
    return rng_.below(2) ? horizontal : vertical;
  }
  return std::abs(dx) >= std::abs(dy) ? horizontal : vertical;
}

Action WallFollowerAgent::act(const Scan& scan) {
  if (behaviour_.seek_goal) {
    memory_.update(scan);
    Action action;
    if (navigator_.towardsSeenGoal(scan, memory_, behaviour_.goal_range, &goal_seen_, &action)) {
      tried_ = -1;  // by touch: a bump after this move is not the rule's; it starts again from the wall side
      probe_ = 0;
      return action;
    }
  }
  // The four neighbours are always in line of sight, so the scan reports them (noise may misreport them).
  const auto wall = [&](int direction) {
    const Cell n = target(Cell{0, 0}, kMoves[direction]);
    const std::int8_t value = scan.at(n.x, n.y);
    return value == kScanObstacle || value == kScanOutOfBounds;
  };
  const int towards_goal = headingTowards(scan.position(), goal_);  // one draw a step when ties are random
  if (behaviour_.walls_by_touch) return feel(scan, towards_goal);
  if (engaged_ && behaviour_.leave_wall_for_goal && !wall(towards_goal)) {
    engaged_ = false;
    left_a_wall_ = true;
  }
  if (!engaged_) {
    if (!behaviour_.random_wall_start || left_a_wall_) heading_ = towards_goal;
    if (!wall(heading_)) return kMoves[heading_];
    engaged_ = true;
    heading_ = (heading_ + awayFromWall()) % 4;  // the wall just hit is now on the agent's side
  }
  for (int rank = 0; rank < 4; ++rank) {
    const int direction = ruleMove(rank);
    if (!wall(direction)) {
      heading_ = direction;
      return kMoves[direction];
    }
  }
  return Action::Stay;
}

int WallFollowerAgent::ruleMove(int rank) const {
  const int towards_wall = 4 - awayFromWall();
  const int turn[4] = {towards_wall, 0, awayFromWall(), 2};
  return (heading_ + turn[rank]) % 4;
}

Action WallFollowerAgent::feel(const Scan& scan, int towards_goal) {
  const bool blocked = tried_ >= 0 && scan.bumped();
  if (!engaged_) {
    if (!blocked) {
      if (!behaviour_.random_wall_start) heading_ = towards_goal;
      tried_ = heading_;
      return kMoves[heading_];
    }
    engaged_ = true;
    heading_ = (tried_ + awayFromWall()) % 4;  // the wall just felt is now on the agent's side
    probe_ = 1;                                 // and known there: straight on first
  } else if (blocked) {
    probe_ = std::min(probe_ + 1, 3);
  } else if (tried_ >= 0) {
    heading_ = tried_;  // it moved: the wall side first again
    probe_ = 0;
  }
  tried_ = ruleMove(probe_);
  return kMoves[tried_];
}

}  // namespace agents
}  // namespace ppp
