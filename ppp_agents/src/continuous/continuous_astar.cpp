#include "ppp_agents/continuous/continuous_astar.hpp"

#include <utility>
#include <vector>

#include "ppp_core/continuous_episode.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/reachability.hpp"
#include "ppp_core/square_world.hpp"

namespace ppp {
namespace agents {

namespace {

constexpr int kSteps[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};

/// A shortest 4-connected route from `start` to `goal` on `space` (empty when there is none), keeping its
/// direction where routes tie.
std::vector<Cell> straightestRoute(const Grid& space, Cell start, Cell goal) {
  std::vector<Cell> route;
  if (!space.isFree(start) || !space.isFree(goal)) return route;
  const std::vector<int> to_goal = stepDistances(space, goal);
  if (to_goal[space.index(start)] < 0) return route;
  route.push_back(start);
  int heading = -1;
  for (Cell at = start; at != goal;) {
    int chosen = -1;
    for (int k = 0; k < 4; ++k) {
      const Cell next{at.x + kSteps[k][0], at.y + kSteps[k][1]};
      if (!space.isFree(next) || to_goal[space.index(next)] != to_goal[space.index(at)] - 1) continue;
      if (chosen < 0 || k == heading) chosen = k;
    }
    heading = chosen;
    at = Cell{at.x + kSteps[chosen][0], at.y + kSteps[chosen][1]};
    route.push_back(at);
  }
  return route;
}

}  // namespace

std::vector<MapPoint> centreRoute(const Grid& map, const MapFrame& frame, double radius, MapPoint from, MapPoint to) {
  const SquareWorld world(map, frame.resolution);
  const Grid space = continuousConfigurationSpace(world, radius);
  std::vector<MapPoint> path;
  for (const Cell& c : straightestRoute(space, world.cellAt(from.x, from.y), world.cellAt(to.x, to.y))) {
    path.push_back(MapPoint{frame.centreX(c), frame.centreY(c)});
  }
  return path;
}

void ContinuousAstar::start(const ContinuousStart& start) {
  if (start.prior_map == nullptr) throw InvalidArgument("type", "astar in continuous motion needs the true map");
  std::vector<MapPoint> path =
      centreRoute(*start.prior_map, start.frame, start.radius, MapPoint{start.pose.x, start.pose.y}, start.goal);
  if (path.empty()) path.push_back(MapPoint{start.pose.x, start.pose.y});  // no route: it stays
  follower_.follow(std::move(path), start.frame.resolution, start.limits, start.control_period);
}

}  // namespace agents
}  // namespace ppp
