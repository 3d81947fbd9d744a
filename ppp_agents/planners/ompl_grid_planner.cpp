#include "ompl_grid_planner.hpp"

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "grid_motion_validator.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace planners {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

ob::PlannerPtr makePlanner(const std::string& name, const ob::SpaceInformationPtr& si) {
  if (name == "RRTstar") return std::make_shared<og::RRTstar>(si);
  if (name == "PRM") return std::make_shared<og::PRM>(si);
  return std::make_shared<og::RRTConnect>(si);
}

}  // namespace

const std::vector<std::string>& omplPlannerNames() {
  static const std::vector<std::string> names{"RRTConnect", "RRTstar", "PRM"};
  return names;
}

void OmplPlannerOptions::validate() const {
  const std::vector<std::string>& names = omplPlannerNames();
  if (std::find(names.begin(), names.end(), planner) == names.end()) {
    std::string valid;
    for (const std::string& name : names) valid += (valid.empty() ? "" : ", ") + name;
    throw InvalidArgument("planner", "unknown OMPL planner '" + planner + "'; valid: " + valid);
  }
  if (!(planning_time > 0.0) || !std::isfinite(planning_time)) {
    throw InvalidArgument("planning_time",
                          "expected a positive, finite number of seconds, got " + std::to_string(planning_time));
  }
}

OmplGridPlanner::OmplGridPlanner(OmplPlannerOptions options) : options_(std::move(options)) { options_.validate(); }

std::vector<MapPoint> OmplGridPlanner::plan(const GridMap& map, Cell start, Cell goal) const {
  if (!map.passable(start) || !map.passable(goal)) return {};
  if (start == goal) return {map.centre(start)};

  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0.0);
  bounds.setHigh(0, map.frame().width * map.frame().resolution);
  bounds.setHigh(1, map.frame().height * map.frame().resolution);
  space->setBounds(bounds);

  og::SimpleSetup setup(space);
  const ob::SpaceInformationPtr& si = setup.getSpaceInformation();
  setup.setStateValidityChecker([&map](const ob::State* state) { return map.passable(map.cellOf(pointOf(state))); });
  si->setMotionValidator(std::make_shared<GridMotionValidator>(si, map));
  setup.setPlanner(makePlanner(options_.planner, si));

  ob::ScopedState<> from(space);
  ob::ScopedState<> to(space);
  const MapPoint start_point = map.centre(start);
  const MapPoint goal_point = map.centre(goal);
  from[0] = start_point.x;
  from[1] = start_point.y;
  to[0] = goal_point.x;
  to[1] = goal_point.y;
  setup.setStartAndGoalStates(from, to);

  if (setup.solve(options_.planning_time) != ob::PlannerStatus::EXACT_SOLUTION) return {};
  setup.simplifySolution();
  std::vector<MapPoint> waypoints;
  for (const ob::State* state : setup.getSolutionPath().getStates()) waypoints.push_back(pointOf(state));
  return waypoints;
}

}  // namespace planners
}  // namespace ppp
