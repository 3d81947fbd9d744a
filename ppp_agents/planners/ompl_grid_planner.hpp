#pragma once

#include <string>
#include <vector>

#include "grid_map.hpp"
#include "ppp_core/grid.hpp"

namespace ppp {
namespace planners {

/// The OMPL planners OmplPlannerOptions::planner may name.
const std::vector<std::string>& omplPlannerNames();

/// What OmplGridPlanner runs.
struct OmplPlannerOptions {
  std::string planner = "RRTConnect";  ///< One of omplPlannerNames().
  double planning_time = 1.0;          ///< Seconds OMPL may plan per request.
  int seed = 1;                        ///< Each plan's random numbers derive from it and from the request.

  /// @throws InvalidArgument naming `planner` or `planning_time` (positive, finite) when out of range.
  void validate() const;
};

/// OMPL geometric planning on a GridMap (ompl::geometric::SimpleSetup): states are map-frame points in a
/// 2-D real vector space bounded by the map; a state is valid when its cell is passable, a motion when every
/// cell it walks through is (GridMotionValidator), so the planner bridge accepts every path it returns.
/// Each plan draws its samples and shortcuts from random numbers seeded by the options' seed and the request (map,
/// start, goal), not from OMPL's process-wide stream: the same request gets the same plan whatever was planned
/// before, in this process or another (within the planning time: a plan cut short by it depends on the machine).
class OmplGridPlanner {
 public:
  /// @throws InvalidArgument when the options are out of range.
  explicit OmplGridPlanner(OmplPlannerOptions options);

  /// Simplified waypoints from the start cell's centre to the goal cell's centre; empty when a cell is not
  /// passable or OMPL finds no exact solution within the planning time.
  std::vector<MapPoint> plan(const GridMap& map, Cell start, Cell goal) const;

  /// The options in effect.
  const OmplPlannerOptions& options() const { return options_; }

 private:
  OmplPlannerOptions options_;
};

}  // namespace planners
}  // namespace ppp
