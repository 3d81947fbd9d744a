#include "ompl_grid_planner.hpp"

#include <gtest/gtest.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "grid_motion_validator.hpp"
#include "map_picture.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/segment_walk.hpp"

namespace ppp {
namespace planners {
namespace {

using Picture = std::vector<std::string>;

/// OMPL's random numbers are process-global: seed them once, before the first plan.
const bool kOmplSeeded = [] {
  ompl::RNG::setSeed(1);
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  return true;
}();

/// Every cell the robot walks along the waypoints, as the planner bridge expands them.
std::vector<Cell> walked(const GridMap& map, const std::vector<MapPoint>& waypoints) {
  std::vector<Cell> cells;
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    const std::vector<Cell> segment =
        walkMapSegment(map.frame(), waypoints[i - 1].x, waypoints[i - 1].y, waypoints[i].x, waypoints[i].y);
    cells.insert(cells.end(), segment.begin() + (cells.empty() ? 0 : 1), segment.end());
  }
  return cells;
}

/// Plans S -> G on a drawn map and checks the walked path: from S to G, never onto an obstacle.
void expectSolved(const Picture& picture, const OmplPlannerOptions& options) {
  const GridMap map = test::mapPicture(picture);
  const Cell start = test::markedCell(picture, 'S');
  const Cell goal = test::markedCell(picture, 'G');
  const std::vector<MapPoint> waypoints = OmplGridPlanner(options).plan(map, start, goal);
  ASSERT_GE(waypoints.size(), 2u) << options.planner;
  EXPECT_EQ(map.cellOf(waypoints.front()), start);
  EXPECT_DOUBLE_EQ(waypoints.back().x, map.centre(goal).x);
  EXPECT_DOUBLE_EQ(waypoints.back().y, map.centre(goal).y);
  const std::vector<Cell> cells = walked(map, waypoints);
  EXPECT_EQ(cells.back(), goal);
  for (const Cell cell : cells)
    EXPECT_TRUE(map.passable(cell)) << options.planner << ": walks onto " << cell.x << ", " << cell.y;
}

const Picture kOpen = {
    "S.........", "..........", "..........", "..........", "..........",
    "..........", "..........", "..........", "..........", ".........G",
};

const Picture kWall = {
    "S....#....", ".....#....", ".....#....", ".....#....", ".....#....",
    ".....#....", ".....#....", ".....#....", ".....#....", ".........G",
};

TEST(OmplGridPlannerTest, SolvesAnOpenMap) { expectSolved(kOpen, OmplPlannerOptions{}); }

TEST(OmplGridPlannerTest, SolvesAMapWithAWallWithEveryPlanner) {
  for (const std::string& name : omplPlannerNames()) expectSolved(kWall, OmplPlannerOptions{name, 0.2});
}

TEST(OmplGridPlannerTest, FailsCleanlyWhenTheGoalIsWalledOff) {
  const Picture walled = {
      "S.........", "..........", "..........", "..........", "..........",
      "..........", "..........", "..........", "........##", "........#G",
  };
  const GridMap map = test::mapPicture(walled);
  const OmplGridPlanner planner(OmplPlannerOptions{"RRTConnect", 0.2});
  EXPECT_TRUE(planner.plan(map, Cell{0, 0}, Cell{9, 9}).empty());
  EXPECT_TRUE(planner.plan(map, Cell{0, 0}, Cell{8, 9}).empty());  // the goal itself is an obstacle
  EXPECT_EQ(planner.plan(map, Cell{3, 4}, Cell{3, 4}).size(), 1u);
}

TEST(OmplGridPlannerTest, TheSameRequestGetsTheSamePlanWhateverWasPlannedBefore) {
  // A plan's random numbers come from the seed and the request: a fresh planner, and one that planned on another
  // map in between, give the same waypoints (each instance of a planner agent plays its own share of the runs).
  const GridMap wall = test::mapPicture(kWall);
  const GridMap open = test::mapPicture(kOpen);
  const Cell start = test::markedCell(kWall, 'S');
  const Cell goal = test::markedCell(kWall, 'G');
  const OmplGridPlanner planner{OmplPlannerOptions{}};
  const std::vector<MapPoint> first = planner.plan(wall, start, goal);
  ASSERT_GE(first.size(), 2u);
  for (int i = 0; i < 3; ++i) planner.plan(open, start, test::markedCell(kOpen, 'G'));
  const std::vector<MapPoint> again = planner.plan(wall, start, goal);
  const std::vector<MapPoint> fresh = OmplGridPlanner(OmplPlannerOptions{}).plan(wall, start, goal);
  for (const std::vector<MapPoint>* other : {&again, &fresh}) {
    ASSERT_EQ(other->size(), first.size());
    for (std::size_t i = 0; i < first.size(); ++i) {
      EXPECT_EQ((*other)[i].x, first[i].x) << i;
      EXPECT_EQ((*other)[i].y, first[i].y) << i;
    }
  }
}

/// The options with their limits replaced: wall-clock seconds and iterations (0: none).
OmplPlannerOptions limited(double planning_time, int planning_iterations) {
  OmplPlannerOptions options;
  options.planning_time = planning_time;
  options.planning_iterations = planning_iterations;
  return options;
}

TEST(OmplGridPlannerTest, AnIterationLimitCutsAPlanShort) {
  // Every route here bends at least twice (down the first gap, up through the second). One RRTConnect iteration
  // extends the start tree by one straight motion and pulls the goal tree straight towards it: a route with one
  // bend at most, so a limit of 1 finds nothing, on any machine; the default limit finds a path.
  const Picture zigzag = {
      "S..#......", "...#......", "...#..#...", "...#..#...", "...#..#...",
      "...#..#...", "...#..#...", "...#..#...", "......#...", "......#..G",
  };
  const GridMap map = test::mapPicture(zigzag);
  const Cell start = test::markedCell(zigzag, 'S');
  const Cell goal = test::markedCell(zigzag, 'G');
  EXPECT_TRUE(OmplGridPlanner(limited(0.0, 1)).plan(map, start, goal).empty());
  expectSolved(zigzag, OmplPlannerOptions{});
}

TEST(OmplGridPlannerTest, EitherLimitEndsAPlanForAGoalThatCannotBeReached) {
  const Picture walled = {
      "S.........", "..........", "..........", "..........", "..........",
      "..........", "..........", "..........", "........##", "........#G",
  };
  const GridMap map = test::mapPicture(walled);
  EXPECT_TRUE(OmplGridPlanner(limited(0.0, 2000)).plan(map, Cell{0, 0}, Cell{9, 9}).empty());
  EXPECT_TRUE(OmplGridPlanner(limited(0.01, 0)).plan(map, Cell{0, 0}, Cell{9, 9}).empty());
}

TEST(OmplGridPlannerTest, RefusesBadOptions) {
  EXPECT_THROW(OmplGridPlanner(OmplPlannerOptions{"RRT", 1.0}), InvalidArgument);
  const std::vector<std::pair<OmplPlannerOptions, std::string>> bad = {
      {limited(-1.0, 100), "planning_time"},
      {limited(std::numeric_limits<double>::infinity(), 100), "planning_time"},
      {limited(1.0, -1), "planning_iterations"},
  };
  for (const auto& [options, name] : bad) {
    try {
      OmplGridPlanner{options};
      ADD_FAILURE() << "no error for " << name;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.name(), name);
    }
  }
  EXPECT_NO_THROW(OmplGridPlanner(limited(0.0, 1)));
  EXPECT_NO_THROW(OmplGridPlanner(limited(0.0, 0)));  // the planner's default iteration limit
  EXPECT_EQ(defaultPlanningIterations("RRTConnect"), 100000);
  EXPECT_EQ(defaultPlanningIterations("RRTstar"), 10000);
}

TEST(GridMotionValidatorTest, AgreesWithTheWalkedCells) {
  const GridMap map = test::mapPicture(kWall);
  auto space = std::make_shared<ompl::base::RealVectorStateSpace>(2);
  space->setBounds(0.0, 10.0);
  auto si = std::make_shared<ompl::base::SpaceInformation>(space);
  const GridMotionValidator validator(si, map);
  ompl::base::State* from = space->allocState();
  ompl::base::State* to = space->allocState();
  ompl::base::State* last = space->allocState();
  Rng rng(5);
  int invalid = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    // Half the points on half-cell multiples, so that many motions pass exactly through cell corners.
    const auto coordinate = [&] { return trial % 2 ? rng.uniformInt(1, 19) / 2.0 : rng.uniform01() * 10.0; };
    double* a = from->as<ompl::base::RealVectorStateSpace::StateType>()->values;
    double* b = to->as<ompl::base::RealVectorStateSpace::StateType>()->values;
    a[0] = coordinate();
    a[1] = coordinate();
    b[0] = coordinate();
    b[1] = coordinate();
    if (!map.passable(map.cellOf(pointOf(from)))) continue;
    const bool expected = map.segmentPassable(pointOf(from), pointOf(to));
    EXPECT_EQ(validator.checkMotion(from, to), expected) << trial;
    std::pair<ompl::base::State*, double> last_valid{last, -1.0};
    EXPECT_EQ(validator.checkMotion(from, to, last_valid), expected) << trial;
    if (expected) continue;
    ++invalid;
    EXPECT_GE(last_valid.second, 0.0);
    EXPECT_LT(last_valid.second, 1.0);
    EXPECT_TRUE(map.segmentPassable(pointOf(from), pointOf(last))) << trial;
  }
  EXPECT_GT(invalid, 100);
  space->freeState(from);
  space->freeState(to);
  space->freeState(last);
}

}  // namespace
}  // namespace planners
}  // namespace ppp
