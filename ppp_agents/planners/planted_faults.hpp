#pragma once

// The fault zoo: the optimistic example planner (optimistic_astar.hpp, re-planning on every map) with one classic
// fault planted, as planner authors make them, for measuring how well a hunt finds a planner's fault
// (scripts/bench-hunt.sh). Each fault is a small change to the search (SearchRules) or to what the planner does with
// its result, and each fails only on some layouts, so the planner passes most ordinary PPPs.

#include <string>
#include <vector>

#include "grid_map.hpp"
#include "optimistic_astar.hpp"

namespace ppp {
namespace planners {

/// One planted fault, as the zoo planner's ~fault parameter names it.
struct PlantedFault {
  std::string name;         ///< e.g. "search_horizon".
  std::string kind;         ///< The family of mistake: "effort limit", "bounds error", ...
  std::string description;  ///< What the planner does wrong, for users.
  int default_limit = 0;    ///< The fault's ~limit when none is given (0: the fault takes none).
};

/// Every planted fault, in a fixed order.
const std::vector<PlantedFault>& plantedFaults();

/// The fault of a name. @throws InvalidArgument("fault", ...) listing the valid names.
const PlantedFault& plantedFault(const std::string& name);

/// The optimistic planner with a planted fault. Two faults keep a memory of the episode (the cell the robot left,
/// the routes it planned): startEpisode() clears it.
class FaultyPlanner {
 public:
  /// @throws InvalidArgument for an unknown fault or a negative limit (0: the fault's default).
  FaultyPlanner(const std::string& fault, int limit);

  /// Every cell from `robot` to `goal` of the route the faulty planner takes, or none.
  std::vector<Cell> plan(const GridMap& map, Cell robot, Cell goal);

  /// Forgets the episode before: a new one starts.
  void startEpisode();

 private:
  /// Counts a new route (one that is not what was left of the last): true while within the limit.
  bool routeChangeAllowed(const std::vector<Cell>& route, Cell robot);

  std::string fault_;
  int limit_;
  Cell last_robot_{-1, -1};      // where the robot stood at the last plan
  Cell left_cell_{-1, -1};       // the cell it stood on before that one
  std::vector<Cell> last_route_;  // the last route sent
  int route_changes_ = 0;
};

}  // namespace planners
}  // namespace ppp
