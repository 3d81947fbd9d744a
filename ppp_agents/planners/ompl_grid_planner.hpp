#pragma once

#include <string>
#include <vector>

#include "grid_map.hpp"
#include "ppp_core/grid.hpp"

namespace ppp {
namespace planners {

/// The OMPL planners OmplPlannerOptions::planner may name.
const std::vector<std::string>& omplPlannerNames();

/// The iteration limit of a plan when OmplPlannerOptions leave it at 0: 100,000 for RRTConnect (far more than it
/// needs on any solvable 20x20 PPP; about 0.2 s when the goal cannot be reached) and PRM, 10,000 for RRTstar (which
/// improves its path until the limit: about half a second).
int defaultPlanningIterations(const std::string& planner);

/// What OmplGridPlanner runs.
struct OmplPlannerOptions {
  std::string planner = "RRTConnect";  ///< One of omplPlannerNames().
  double planning_time = 0.0;          ///< Wall-clock seconds OMPL may plan per request (0: no such limit).
  int seed = 1;                        ///< Each plan's random numbers derive from it and from the request.
  int planning_iterations = 0;         ///< Planner iterations per request; 0: defaultPlanningIterations(planner).

  /// The iteration limit in effect: planning_iterations, or the planner's default when it is 0.
  int iterationLimit() const;
  /// @throws InvalidArgument naming `planner`, `planning_time` (not negative, finite) or `planning_iterations` (not
  /// negative) when out of range.
  void validate() const;
};

/// OMPL geometric planning on a GridMap (ompl::geometric::SimpleSetup): states are map-frame points in a
/// 2-D real vector space bounded by the map; a state is valid when its cell is passable, a motion when every
/// cell it walks through is (GridMotionValidator), so the planner bridge accepts every path it returns.
/// Each plan draws its samples and shortcuts from random numbers seeded by the options' seed and the request (map,
/// start, goal), not from OMPL's process-wide stream: the same request gets the same plan whatever was planned
/// before, in this process or another. The iteration limit keeps that true whatever the machine's load; a plan cut
/// short by the wall-clock limit depends on the machine (and PRM grows its roadmap on a timer, so its plans always
/// do).
class OmplGridPlanner {
 public:
  /// @throws InvalidArgument when the options are out of range.
  explicit OmplGridPlanner(OmplPlannerOptions options);

  /// Simplified waypoints from the start cell's centre to the goal cell's centre; empty when a cell is not
  /// passable or OMPL finds no exact solution within the limits.
  std::vector<MapPoint> plan(const GridMap& map, Cell start, Cell goal) const;

  /// The options in effect.
  const OmplPlannerOptions& options() const { return options_; }

 private:
  OmplPlannerOptions options_;
};

}  // namespace planners
}  // namespace ppp
