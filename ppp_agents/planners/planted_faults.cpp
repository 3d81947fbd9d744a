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

std::vector<std::string> plantedFaultList(const std::string& list) {
  std::vector<std::string> faults;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t comma = list.find(',', begin);
    std::string name = list.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin);
    name.erase(0, name.find_first_not_of(' '));
    name.erase(name.find_last_not_of(' ') + 1);
    if (name.empty()) throw InvalidArgument("fault", "an empty fault in '" + list + "'; expected names separated by commas");
    plantedFault(name);  // an unknown name is refused, listing the valid ones
    if (std::find(faults.begin(), faults.end(), name) != faults.end()) {
      throw InvalidArgument("fault", "fault '" + name + "' is planted twice in '" + list + "'");
    }
    faults.push_back(name);
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  const auto has = [&faults](const char* name) { return std::find(faults.begin(), faults.end(), name) != faults.end(); };
  if (has("dead_end_filter") && has("goal_clearance")) {
    throw InvalidArgument("fault", "dead_end_filter cannot be planted with goal_clearance: every goal it takes for an "
                                   "obstacle has a known obstacle beside it, so goal_clearance refuses that goal first "
                                   "and dead_end_filter never fails a run alone");
  }
  return faults;
}

FaultyPlanner::FaultyPlanner(const std::string& faults, int limit) : faults_(plantedFaultList(faults)), limit_(limit) {
  if (limit < 0) throw InvalidArgument("limit", "expected 0 (the fault's default) or more, got " + std::to_string(limit));
  int limited = 0;
  for (const std::string& f : faults_) limited += plantedFault(f).default_limit > 0 ? 1 : 0;
  if (limit > 0 && limited > 1) {
    throw InvalidArgument("limit", "a limit of " + std::to_string(limit) + " for '" + faults +
                                       "', where several faults take one; leave it 0 (each fault's default)");
  }
}

bool FaultyPlanner::planted(const char* fault) const {
  return std::find(faults_.begin(), faults_.end(), fault) != faults_.end();
}

int FaultyPlanner::limitOf(const char* fault) const { return limit_ > 0 ? limit_ : plantedFault(fault).default_limit; }

void FaultyPlanner::startEpisode() {
  last_robot_ = left_cell_ = Cell{-1, -1};
  last_route_.clear();
  route_changes_ = 0;
}

bool FaultyPlanner::routeChangeAllowed(const std::vector<Cell>& route, Cell robot, int limit) {
  const auto on_last = std::find(last_route_.begin(), last_route_.end(), robot);
  const bool same = on_last != last_route_.end() && std::equal(on_last, last_route_.end(), route.begin(), route.end());
  last_route_ = route;
  if (!same) ++route_changes_;
  return route_changes_ <= limit;
}

std::vector<Cell> FaultyPlanner::plan(const GridMap& map, Cell robot, Cell goal) {
  if (robot != last_robot_) {
    left_cell_ = last_robot_;
    last_robot_ = robot;
  }
  if (planted("goal_clearance") && nearKnownObstacle(map, goal)) return {};
  SearchRules rules;
  if (planted("expansion_budget")) rules.max_expansions = limitOf("expansion_budget");
  if (planted("open_list_cap")) rules.max_open = limitOf("open_list_cap");
  const bool west_edge = planted("west_edge"), dead_end = planted("dead_end_filter"), no_backtrack = planted("no_backtrack");
  if (west_edge || dead_end || no_backtrack) {
    const Cell left = left_cell_;
    rules.can_step = [&map, left, west_edge, dead_end, no_backtrack](Cell from, Cell to) {
      return map.passable(to) && !(west_edge && to.x == 0 && from.x == 1) && !(dead_end && blockedSides(map, to) >= 3) &&
             !(no_backtrack && to == left);
    };
  }
  std::vector<Cell> route = gridAStar(map, robot, goal, rules);
  if (planted("replan_limit") && !routeChangeAllowed(route, robot, limitOf("replan_limit"))) return {};
  if (planted("search_horizon") && static_cast<int>(route.size()) > limitOf("search_horizon")) return {};
  return route;
}

}  // namespace planners
}  // namespace ppp
