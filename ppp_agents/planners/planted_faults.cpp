#include "planted_faults.hpp"

#include <algorithm>

#include "ppp_core/error.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {
namespace planners {

const std::vector<PlantedFault>& plantedFaults() {
  static const std::vector<PlantedFault> faults = {
      {"search_horizon", "effort limit", "gives up (no path) on any route longer than ~limit cells", 45},
      {"expansion_budget", "effort limit", "A* gives up (no path) after expanding ~limit cells", 200},
      {"west_edge", "bounds error",
       "its bounds check for a step west is x - 1 > 0 where it should be x - 1 >= 0: it never steps west into the "
       "map's left column",
       0},
      {"goal_clearance", "obstacle handling",
       "refuses (no path) a goal with a known obstacle in any of its eight neighbouring cells: a clearance check "
       "meant for a robot with a body",
       0},
      {"dead_end_filter", "obstacle handling",
       "a noise filter takes every free cell with three blocked sides (the map's edge counting as blocked) for an "
       "obstacle: a goal in a pocket is never planned to",
       0},
      {"open_list_cap", "effort limit",
       "A* keeps its open list in a fixed array of ~limit cells and gives up (no path) when it overflows: wide "
       "open fronts of search are too much for it",
       80},
      {"no_backtrack", "reactive choice",
       "never plans through the cell it last planned from, the one the robot has just left while each step shows "
       "a new map (a rule against dithering): from the end of a dead end it finds no way out",
       0},
      {"replan_limit", "re-planning fault",
       "gives up (no path) once it has planned more than ~limit different routes in an episode (a retry limit set "
       "too low)",
       30},
  };
  return faults;
}

const PlantedFault& plantedFault(const std::string& name) {
  const std::vector<PlantedFault>& faults = plantedFaults();
  const auto found = std::find_if(faults.begin(), faults.end(), [&](const PlantedFault& f) { return f.name == name; });
  if (found != faults.end()) return *found;
  std::vector<std::string> names;
  for (const PlantedFault& f : faults) names.push_back(f.name);
  throw InvalidArgument("fault", "unknown fault '" + name + "'; expected one of " + joinNames(names));
}

namespace {

constexpr Cell kSteps[] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};

/// The cell's sides that are blocked (off the map or not passable).
int blockedSides(const GridMap& map, Cell c) {
  int sides = 0;
  for (const Cell s : kSteps) sides += map.passable(Cell{c.x + s.x, c.y + s.y}) ? 0 : 1;
  return sides;
}

/// True when one of the eight cells around `c` is on the map and not passable (a known obstacle).
bool nearKnownObstacle(const GridMap& map, Cell c) {
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const Cell n{c.x + dx, c.y + dy};
      if ((dx != 0 || dy != 0) && map.contains(n) && !map.passable(n)) return true;
    }
  }
  return false;
}

}  // namespace

FaultyPlanner::FaultyPlanner(const std::string& fault, int limit) : fault_(plantedFault(fault).name), limit_(limit) {
  if (limit < 0) throw InvalidArgument("limit", "expected 0 (the fault's default) or more, got " + std::to_string(limit));
  if (limit_ == 0) limit_ = plantedFault(fault).default_limit;
}

void FaultyPlanner::startEpisode() {
  last_robot_ = left_cell_ = Cell{-1, -1};
  last_route_.clear();
  route_changes_ = 0;
}

bool FaultyPlanner::routeChangeAllowed(const std::vector<Cell>& route, Cell robot) {
  const auto on_last = std::find(last_route_.begin(), last_route_.end(), robot);
  const bool same = on_last != last_route_.end() && std::equal(on_last, last_route_.end(), route.begin(), route.end());
  last_route_ = route;
  if (!same) ++route_changes_;
  return route_changes_ <= limit_;
}

std::vector<Cell> FaultyPlanner::plan(const GridMap& map, Cell robot, Cell goal) {
  if (robot != last_robot_) {
    left_cell_ = last_robot_;
    last_robot_ = robot;
  }
  SearchRules rules;
  if (fault_ == "search_horizon") {
    std::vector<Cell> route = optimisticAStar(map, robot, goal);
    return static_cast<int>(route.size()) > limit_ ? std::vector<Cell>{} : route;
  }
  if (fault_ == "expansion_budget") {
    rules.max_expansions = limit_;
  } else if (fault_ == "west_edge") {
    rules.can_step = [&map](Cell from, Cell to) { return map.passable(to) && !(to.x == 0 && from.x == 1); };
  } else if (fault_ == "dead_end_filter") {
    rules.can_step = [&map](Cell, Cell to) { return map.passable(to) && blockedSides(map, to) < 3; };
  } else if (fault_ == "open_list_cap") {
    rules.max_open = limit_;
  } else if (fault_ == "goal_clearance") {
    if (nearKnownObstacle(map, goal)) return {};
  } else if (fault_ == "no_backtrack") {
    const Cell left = left_cell_;
    rules.can_step = [&map, left](Cell, Cell to) { return to != left && map.passable(to); };
  } else if (fault_ == "replan_limit") {
    const std::vector<Cell> route = optimisticAStar(map, robot, goal);
    return routeChangeAllowed(route, robot) ? route : std::vector<Cell>{};
  }
  return gridAStar(map, robot, goal, rules);
}

}  // namespace planners
}  // namespace ppp
