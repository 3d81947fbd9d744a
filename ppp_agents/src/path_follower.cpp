#include "ppp_agents/path_follower.hpp"

#include <algorithm>
#include <cstdlib>

#include "ppp_core/error.hpp"
#include "ppp_core/segment_walk.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {
namespace agents {

bool samePoints(const std::vector<MapPoint>& a, const std::vector<MapPoint>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const MapPoint& p, const MapPoint& q) { return p.x == q.x && p.y == q.y; });
}

std::int8_t KnownMap::at(Cell c) const {
  if (c.x < 0 || c.y < 0 || c.x >= width || c.y >= height) return kScanOutOfBounds;
  return cells[static_cast<std::size_t>(c.y * width + c.x)];
}

std::string PathFollower::follow(const std::vector<MapPoint>& waypoints, const MapFrame& frame, Cell robot,
                                 Cell goal, const KnownMap& known) {
  if (waypoints.empty()) return "the path is empty";
  std::vector<Cell> walk;
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    const MapPoint& from = waypoints[i];
    const MapPoint& to = i + 1 < waypoints.size() ? waypoints[i + 1] : waypoints[i];
    std::vector<Cell> cells;
    try {
      cells = walkMapSegment(frame, from.x, from.y, to.x, to.y);
    } catch (const InvalidArgument& e) {
      return std::string("the path has a pose far off the map (") + e.what() + ")";
    }
    for (Cell c : cells) {
      if (walk.empty() || !(walk.back() == c)) walk.push_back(c);
    }
  }
  for (Cell c : walk) {
    if (known.at(c) == kScanOutOfBounds) return "the path leaves the map at cell " + cellText(c);
  }
  std::size_t position = walk.size();
  for (std::size_t i = 0; i < walk.size() && position == walk.size(); ++i) {
    if (walk[i] == robot) position = i;
  }
  if (position == walk.size()) {
    return "the path does not pass through the robot's cell " + cellText(robot) + " (it starts at " +
           cellText(walk.front()) + ")";
  }
  for (std::size_t i = position + 1; i < walk.size(); ++i) {
    if (known.at(walk[i]) == kScanObstacle) return "the path crosses the obstacle cell " + cellText(walk[i]);
  }
  if (!(walk.back() == goal)) {
    return "the path ends at cell " + cellText(walk.back()) + ", not at the goal " + cellText(goal);
  }
  walk_ = std::move(walk);
  position_ = position;
  return "";
}

std::optional<Action> PathFollower::next(Cell robot, const KnownMap& known) {
  if (walk_.empty()) return std::nullopt;
  for (std::size_t skip = 1; skip <= 2; ++skip) {  // one cell of the walk, or two after a diagonal
    if (position_ + skip < walk_.size() && walk_[position_ + skip] == robot) {
      position_ += skip;
      break;
    }
  }
  if (!(walk_[position_] == robot) || position_ + 1 >= walk_.size()) return std::nullopt;
  const Cell ahead = walk_[position_ + 1];
  if (known.at(ahead) == kScanObstacle) return std::nullopt;
  if (connectivity_ == Connectivity::Eight && position_ + 2 < walk_.size()) {
    const Cell beyond = walk_[position_ + 2];
    const Cell side{robot.x + beyond.x - ahead.x, robot.y + beyond.y - ahead.y};  // the corner's other side
    const bool corner = std::abs(beyond.x - robot.x) == 1 && std::abs(beyond.y - robot.y) == 1;
    if (corner && known.at(ahead) == kScanFree && known.at(side) == kScanFree && known.at(beyond) == kScanFree) {
      return actionTowards(robot, beyond);
    }
  }
  return actionTowards(robot, ahead);
}

void PathFollower::clear() {
  walk_.clear();
  position_ = 0;
}

void PathFollower::addTo(StateDigest* digest) const {
  digest->add(static_cast<std::int64_t>(walk_.size()));
  for (const Cell& c : walk_) {
    digest->add(c.x);
    digest->add(c.y);
  }
  digest->add(static_cast<std::int64_t>(position_));
  digest->add(static_cast<int>(connectivity_));
}

}  // namespace agents
}  // namespace ppp
