#include "ppp_agents/wall_follower_agent.hpp"

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
    if (navigator_.towardsSeenGoal(scan, memory_, behaviour_.goal_range, &goal_seen_, &action)) return action;
  }
  // The four neighbours are always in line of sight, so the scan reports them (noise may misreport them).
  const auto wall = [&](int direction) {
    const Cell n = target(Cell{0, 0}, kMoves[direction]);
    const std::int8_t value = scan.at(n.x, n.y);
    return value == kScanObstacle || value == kScanOutOfBounds;
  };
  const int towards_wall = side_ == Side::Left ? 3 : 1;  // quarter turns clockwise: left = 3, right = 1
  const int away_from_wall = 4 - towards_wall;
  const int towards_goal = headingTowards(scan.position(), goal_);  // one draw a step when ties are random
  if (engaged_ && behaviour_.leave_wall_for_goal && !wall(towards_goal)) {
    engaged_ = false;
    left_a_wall_ = true;
  }
  if (!engaged_) {
    if (!behaviour_.random_wall_start || left_a_wall_) heading_ = towards_goal;
    if (!wall(heading_)) return kMoves[heading_];
    engaged_ = true;
    heading_ = (heading_ + away_from_wall) % 4;  // the wall just hit is now on the agent's side
  }
  const int order[4] = {(heading_ + towards_wall) % 4, heading_, (heading_ + away_from_wall) % 4, (heading_ + 2) % 4};
  for (int direction : order) {
    if (!wall(direction)) {
      heading_ = direction;
      return kMoves[direction];
    }
  }
  return Action::Stay;
}

}  // namespace agents
}  // namespace ppp
