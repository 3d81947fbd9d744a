#include "ompl_grid_planner.hpp"

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <utility>

#include "grid_motion_validator.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace planners {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

/// OMPL's uniform sampler of a real vector space, its random numbers seeded (not drawn from OMPL's global stream).
class SeededSampler : public ob::RealVectorStateSampler {
 public:
  SeededSampler(const ob::StateSpace* space, std::uint_fast32_t seed) : ob::RealVectorStateSampler(space) {
    rng_.setLocalSeed(seed);
  }
};

/// OMPL's path simplifier, its random shortcuts seeded.
class SeededSimplifier : public og::PathSimplifier {
 public:
  SeededSimplifier(const ob::SpaceInformationPtr& si, std::uint_fast32_t seed) : og::PathSimplifier(si) {
    rng_.setLocalSeed(seed);
  }
};

/// The seed of a plan: the options' seed, the start, the goal and every passable cell of the map.
std::uint_fast32_t planSeed(int seed, const GridMap& map, Cell start, Cell goal) {
  std::uint64_t cells = 14695981039346656037ULL;  // FNV-1a over the passable flags
  for (int y = 0; y < map.frame().height; ++y) {
    for (int x = 0; x < map.frame().width; ++x) {
      cells = (cells ^ (map.passable(Cell{x, y}) ? 1u : 0u)) * 1099511628211ULL;
    }
  }
  const std::uint64_t derived =
      deriveSeed(static_cast<std::uint64_t>(seed), {static_cast<std::uint64_t>(start.x), static_cast<std::uint64_t>(start.y),
                                                    static_cast<std::uint64_t>(goal.x), static_cast<std::uint64_t>(goal.y), cells});
  return static_cast<std::uint_fast32_t>(derived & 0xffffffffu) | 1u;  // OMPL takes any non-zero seed
}

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
  if (!(planning_time >= 0.0) || !std::isfinite(planning_time)) {
    throw InvalidArgument("planning_time", "expected a finite number of seconds, 0 or more (0: no wall-clock limit), "
                                           "got " + std::to_string(planning_time));
  }
  if (planning_iterations < 0) {
    throw InvalidArgument("planning_iterations",
                          "expected a number of iterations, 0 or more (0: the planner's default), got " +
                              std::to_string(planning_iterations));
  }
}

int defaultPlanningIterations(const std::string& planner) { return planner == "RRTstar" ? 10000 : 100000; }

int OmplPlannerOptions::iterationLimit() const {
  return planning_iterations > 0 ? planning_iterations : defaultPlanningIterations(planner);
}

OmplGridPlanner::OmplGridPlanner(OmplPlannerOptions options) : options_(std::move(options)) { options_.validate(); }

std::vector<MapPoint> OmplGridPlanner::plan(const GridMap& map, Cell start, Cell goal) const {
  if (!map.passable(start) || !map.passable(goal)) return {};
  if (start == goal) return {map.centre(start)};

  const std::uint_fast32_t seed = planSeed(options_.seed, map, start, goal);
  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  space->setStateSamplerAllocator(
      [seed](const ob::StateSpace* s) -> ob::StateSamplerPtr { return std::make_shared<SeededSampler>(s, seed); });
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

  // Counted checks of the limit (one per iteration: the N + 1st check ends the plan, as OMPL's
  // IterationTerminationCondition, but atomic, as PRM checks from two threads) end a plan at the same point on any
  // machine; the wall clock, when set, may end it sooner.
  std::atomic<long long> checks{0};
  const long long iterations = options_.iterationLimit();
  ob::PlannerTerminationCondition limit(
      [&checks, iterations] { return checks.fetch_add(1, std::memory_order_relaxed) >= iterations; });
  if (options_.planning_time > 0.0) {
    limit = ob::plannerOrTerminationCondition(limit, ob::timedPlannerTerminationCondition(options_.planning_time));
  }
  if (setup.solve(limit) != ob::PlannerStatus::EXACT_SOLUTION) return {};
  og::PathGeometric& path = setup.getSolutionPath();
  SeededSimplifier(si, seed).simplifyMax(path);
  std::vector<MapPoint> waypoints;
  for (const ob::State* state : path.getStates()) waypoints.push_back(pointOf(state));
  return waypoints;
}

}  // namespace planners
}  // namespace ppp
