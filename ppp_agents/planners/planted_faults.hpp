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

/// The faults of a comma-separated list ("search_horizon,west_edge"), in the list's order. Faults combine (an
/// effort limit and a bounds error both act on one search), except dead_end_filter with goal_clearance: every goal
/// the filter takes for an obstacle has a known obstacle beside it, so goal_clearance would refuse it first and
/// the filter could never fail a run alone.
/// @throws InvalidArgument("fault", ...) naming an unknown, repeated or unplantable fault, or an empty list.
std::vector<std::string> plantedFaultList(const std::string& list);

/// The optimistic planner with one or more planted faults. Two faults keep a memory of the episode (the cell the
/// robot left, the routes it planned): startEpisode() clears it.
class FaultyPlanner {
 public:
  /// `faults`: a plantedFaultList(). `limit`: the limit of the one planted fault that takes one (0: each fault's
  /// default). @throws InvalidArgument for a bad list, a negative limit, or a limit given to several faults that
  /// take one (it could not say whose it is).
  FaultyPlanner(const std::string& faults, int limit);

  /// Every cell from `robot` to `goal` of the route the faulty planner takes, or none.
  std::vector<Cell> plan(const GridMap& map, Cell robot, Cell goal);

  /// Forgets the episode before: a new one starts.
  void startEpisode();

 private:
  /// Counts a new route (one that is not what was left of the last): true while within `limit`.
  bool routeChangeAllowed(const std::vector<Cell>& route, Cell robot, int limit);

  bool planted(const char* fault) const;
  int limitOf(const char* fault) const;

  std::vector<std::string> faults_;
  int limit_;
  Cell last_robot_{-1, -1};      // where the robot stood at the last plan
  Cell left_cell_{-1, -1};       // the cell it stood on before that one
  std::vector<Cell> last_route_;  // the last route sent
  int route_changes_ = 0;
};

}  // namespace planners
}  // namespace ppp
