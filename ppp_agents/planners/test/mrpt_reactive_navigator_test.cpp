// MRPT's holonomic reactive navigators driven as mrpt_reactive_node drives them, without ROS: obstacle distances
// per direction from the robot's scan, the goal relative to the robot, a direction and speed out, and the robot
// taking the 4-connected move nearest that direction (ppp_agents' commandedMove), as the planner bridge does.
#include "mrpt_reactive_navigator.hpp"

#include <gtest/gtest.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/nav/holonomic/CAbstractHolonomicReactiveMethod.h>
#include <mrpt/nav/holonomic/CHolonomicND.h>
#include <mrpt/nav/holonomic/ClearanceDiagram.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "map_picture.hpp"
#include "reactive_traps.hpp"
#include "ppp_agents/velocity_command.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/scan_rays.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {
namespace planners {
namespace {

using Picture = std::vector<std::string>;

constexpr int kRays = 72;  // as the planner bridge's LaserScan
const double kScanRange = 2.5 * std::sqrt(2.0);  // its range_max for sensor range 2, 1 m cells

/// What one step of a walk chose.
struct Choice {
  Cell robot;
  double degrees = 0;  // the chosen direction
  Action move = Action::Stay;
};

/// What the method is given at `robot` on `grid` (1 m cells), as mrpt_reactive_node gets it from the bridge:
/// the range-2 scan as 72 rays (their angle increment a float, as in sensor_msgs/LaserScan) per sector, and the
/// goal relative to the robot, both as fractions of the scan's range.
struct MethodInput {
  std::vector<double> obstacles;
  MapPoint target;
};

MethodInput inputAt(const Grid& grid, Cell robot, Cell goal) {
  const MapFrame frame{grid.width(), grid.height(), 1.0};
  const SensorModel sensor(SensorOptions{2, 0.0});
  std::vector<std::int8_t> window(25);
  sensor.see(grid, robot, window.data());
  int invalid = 0;
  const LaserRays scan{0, static_cast<float>(2 * M_PI / kRays), windowRanges(window.data(), 2, kRays)};
  return MethodInput{sectorObstacles(scan, kScanRange, &invalid),
                     MapPoint{(frame.centreX(goal) - frame.centreX(robot)) / kScanRange,
                              (frame.centreY(goal) - frame.centreY(robot)) / kScanRange}};
}

/// The robot's walk on a drawn map ('#' obstacles, S start, G goal): at each step the method's choice for
/// inputAt the robot's cell; the robot takes the 4-connected move nearest its direction. Stops on the goal or
/// after `steps` steps.
std::vector<Choice> walk(const Picture& picture, const std::string& method, int steps) {
  const Grid grid = test::pictureGrid(picture);
  const Cell goal = test::markedCell(picture, 'G');
  MrptReactiveNavigator navigator(method);
  Cell robot = test::markedCell(picture, 'S');
  std::vector<Choice> choices;
  for (int step = 0; step < steps && !(robot == goal); ++step) {
    const MethodInput input = inputAt(grid, robot, goal);
    const Heading heading = navigator.navigate(input.obstacles, input.target);
    agents::VelocityCommand command;
    command.linear_x = heading.speed * std::cos(heading.direction);
    command.linear_y = heading.speed * std::sin(heading.direction);
    const Action move = agents::commandedMove(command, Connectivity::Four, 1.0).action;
    choices.push_back(Choice{robot, heading.direction * 180 / M_PI, move});
    const Cell next = ppp::target(robot, move);
    if (grid.contains(next) && grid.isFree(next)) robot = next;
  }
  choices.push_back(Choice{robot, 0, Action::Stay});
  return choices;
}

TEST(MrptReactiveNavigatorTest, UnknownMethodIsRefusedNamingIt) {
  try {
    MrptReactiveNavigator navigator("DWA");
    FAIL() << "accepted DWA";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "method");
    EXPECT_NE(std::string(e.what()).find("valid: ND, VFF, FullEval"), std::string::npos) << e.what();
  }
  MrptReactiveNavigator navigator("VFF");
  EXPECT_THROW(navigator.navigate(std::vector<double>(10, 1.0), MapPoint{1, 0}), InvalidArgument);
  std::vector<double> negative(kReactiveSectors, 1.0);
  negative[3] = -0.5;
  EXPECT_THROW(navigator.navigate(negative, MapPoint{1, 0}), InvalidArgument);
}

// Far from obstacles every method heads for the goal: on an open 8x8 map each reaches a goal inside it along a
// shortest route (8 moves from (0, 0) to (4, 4)).
TEST(MrptReactiveNavigatorTest, EveryMethodCrossesAnOpenMapToAGoalAwayFromItsEdges) {
  const Picture open = {"S.......", "........", "........", "........",
                        "....G...", "........", "........", "........"};
  for (const std::string& method : reactiveMethodNames()) {
    const std::vector<Choice> choices = walk(open, method, 100);
    EXPECT_EQ(choices.back().robot, test::markedCell(open, 'G')) << method;
    EXPECT_EQ(choices.size(), 9u) << method;  // 8 moves, then the goal
  }
}

// A goal in a corner of the map, reached along the map's edge: at (7, 6) the goal lies 1 m south and the map's
// edge, which the scan reports as an obstacle, 0.5 m east and 1.5 m south. ND goes in; VFF's repulsion from
// the edges outweighs the goal's attraction (the potential field's "goal near obstacles" problem) and FullEval
// scores the way west higher: both go back west to (6, 6), and from there east again, for ever.
TEST(MrptReactiveNavigatorTest, VffAndFullEvalNeverEnterAGoalInTheMapsCorner) {
  const Picture& corner = test::trapPicture("corner");
  const std::vector<Choice> nd = walk(corner, "ND", 100);
  EXPECT_EQ(nd.back().robot, test::markedCell(corner, 'G'));
  EXPECT_EQ(nd.size(), 15u);  // 14 moves, then the goal
  for (const std::string& method : {std::string("VFF"), std::string("FullEval")}) {
    const std::vector<Choice> choices = walk(corner, method, 300);
    ASSERT_EQ(choices.size(), 301u) << method << " reached the goal";
    for (std::size_t i = 200; i < 300; i += 2) {
      EXPECT_EQ(choices[i].robot, (Cell{6, 6})) << method << " step " << i;
      EXPECT_EQ(choices[i].move, Action::East) << method << " step " << i;
      EXPECT_EQ(choices[i + 1].robot, (Cell{7, 6})) << method << " step " << i + 1;
      EXPECT_EQ(choices[i + 1].move, Action::West) << method << " step " << i + 1;
    }
  }
}

// The classic trap of reactive navigation: a U whose closed end lies between the robot and the goal. VFF's
// attraction pulls the robot into the closed end, the wall's repulsion pushes it back out: it moves north, then
// south, for ever. The trap is symmetric about the robot's column and the goal lies on it, so VFF's force has no
// east-west part: its directions are exactly ±90°. ND swings between the same two kinds of choice.
TEST(MrptReactiveNavigatorTest, VffAndNdOscillateForEverInAUFacingAwayFromTheGoal) {
  const Picture& trap = test::trapPicture("u");
  for (const std::string& method : {std::string("VFF"), std::string("ND")}) {
    const std::vector<Choice> choices = walk(trap, method, 300);
    ASSERT_EQ(choices.size(), 301u) << method << " reached the goal";
    // A cycle of two cells, north then south, from the second step to the 300th.
    for (std::size_t i = 2; i + 1 < choices.size(); ++i) {
      EXPECT_EQ(choices[i].robot, choices[i - 2].robot) << method << " step " << i;
      EXPECT_EQ(choices[i].move, choices[i - 2].move) << method << " step " << i;
      EXPECT_NEAR(choices[i].degrees, choices[i - 2].degrees, 1e-9) << method << " step " << i;
    }
    EXPECT_NE(choices[10].robot, choices[11].robot) << method;
    for (std::size_t i = 1; i + 1 < choices.size(); ++i) {
      EXPECT_TRUE(choices[i].move == Action::North || choices[i].move == Action::South) << method << " step " << i;
      if (method == "VFF") {
        EXPECT_NEAR(std::fabs(choices[i].degrees), 90.0, 1e-9) << "step " << i;
      }
    }
  }
}

// VFF's commonest trap from its hunted set (the goal at (14, 12) of a 20x20 map), shrunk: two obstacle cells in
// a diagonal just before the goal, touching at their corners; here the same on an 8x8 map. The map is symmetric
// about the diagonal through start and goal, so in the pocket between the two cells VFF's resultant lies on
// that diagonal: the cells' repulsion, 0.5 m away on two sides, outweighs the goal's attraction and points
// exactly away from the goal (135°), a tie that the robot breaks along x (west). One cell west, the goal pulls
// it back (-32.5°, east), for ever.
TEST(MrptReactiveNavigatorTest, VffTurnsBackForEverInThePocketOfTwoDiagonalCellsBeforeTheGoal) {
  const Picture& trap = test::trapPicture("pocket");
  const std::vector<Choice> choices = walk(trap, "VFF", 300);
  ASSERT_EQ(choices.size(), 301u) << "VFF reached the goal";
  for (std::size_t i = 0; i < 8; ++i) {  // down the diagonal, alternating east and south
    EXPECT_EQ(choices[i].robot, (Cell{static_cast<int>((i + 1) / 2), static_cast<int>(i / 2)})) << "step " << i;
  }
  for (std::size_t i = 8; i + 1 < 300; i += 2) {
    EXPECT_EQ(choices[i].robot, (Cell{4, 4})) << "step " << i;
    EXPECT_NEAR(choices[i].degrees, 135.0, 1e-9) << "step " << i;
    EXPECT_EQ(choices[i].move, Action::West) << "step " << i;
    EXPECT_EQ(choices[i + 1].robot, (Cell{3, 4})) << "step " << i + 1;
    EXPECT_EQ(choices[i + 1].move, Action::East) << "step " << i + 1;
    EXPECT_NEAR(choices[i + 1].degrees, choices[9].degrees, 1e-12) << "step " << i + 1;
  }
  EXPECT_NEAR(choices[9].degrees, -32.5, 0.01);
}

// ND's trap from its hunted set, shrunk: one obstacle cell diagonal to a goal in the map's corner (through ROS,
// on a 20x20 map, (18, 18) before the goal (19, 19); here the same corner of a 6x6 map). ND comes down the
// diagonal, turns south round the obstacle's west side, and then swings for ever between the cell west of the
// obstacle, where it heads north (92.5°), and the cell north of that, where it heads south-west (-122.5°).
// MRPT's own log says why: at both cells the way to the goal is closed, so ND picks one of the two wide gaps
// (SITUATION_WIDE_GAP), and for a wide gap it steers 9 sectors (45°) inside the gap's edge nearest the target
// (CHolonomicND::calcRepresentativeSectorForGap): west of the obstacle that is north, away from the goal; at
// the cell north of it, the gap round the west side scores a little higher than the one round the east side
// (0.437 against 0.423) and its direction leads back south-west.
TEST(MrptReactiveNavigatorTest, NdSwingsForEverBesideOneObstacleBeforeAGoalInTheCorner) {
  const Picture& trap = test::trapPicture("one_cell");
  const std::vector<Choice> choices = walk(trap, "ND", 300);
  ASSERT_EQ(choices.size(), 301u) << "ND reached the goal";
  const std::vector<Cell> approach = {{0, 0}, {0, 1}, {1, 1}, {1, 2}, {2, 2}, {2, 3}, {2, 4}};
  for (std::size_t i = 0; i < approach.size(); ++i) EXPECT_EQ(choices[i].robot, approach[i]) << "step " << i;
  for (std::size_t i = 7; i + 1 < 300; i += 2) {
    EXPECT_EQ(choices[i].robot, (Cell{3, 4})) << "step " << i;
    EXPECT_NEAR(choices[i].degrees, 92.5, 1e-9) << "step " << i;
    EXPECT_EQ(choices[i].move, Action::North) << "step " << i;
    EXPECT_EQ(choices[i + 1].robot, (Cell{3, 3})) << "step " << i + 1;
    EXPECT_NEAR(choices[i + 1].degrees, -122.5, 1e-9) << "step " << i + 1;
    EXPECT_EQ(choices[i + 1].move, Action::South) << "step " << i + 1;
  }

  // The same two choices from mrpt::nav::CHolonomicND itself, with its log.
  const Grid grid = test::pictureGrid(trap);
  mrpt::nav::CHolonomicND nd;
  mrpt::nav::ClearanceDiagram clearance;
  struct Expected {
    Cell robot;
    std::vector<std::pair<int, int>> gaps;  // first and last sector of each gap
    unsigned selected;
    std::vector<double> evaluations;  // evaluateGaps' score of each gap, printed to 3 places; none: not asserted
  };
  // Sector k points at -180° + 5k + 2.5°. West of the obstacle the target is in sector 30 and the gaps are
  // [0, 5] (west) and [45, 71] (north): the nearer edge is 45, so 45 + 9 = 54, 92.5°. North of it the target
  // is in sector 27 and the gaps are [0, 20] (round the west side) and [33, 71] (round the east): 20 - 9 = 11,
  // -122.5°.
  const std::vector<Expected> cells = {{{3, 4}, {{0, 5}, {45, 71}}, 54, {}},
                                       {{3, 3}, {{0, 20}, {33, 71}}, 11, {0.437, 0.423}}};
  for (const Expected& expected : cells) {
    const MethodInput input = inputAt(grid, expected.robot, test::markedCell(trap, 'G'));
    mrpt::nav::CAbstractHolonomicReactiveMethod::NavInput in;
    in.obstacles = input.obstacles;
    in.targets = {mrpt::math::TPoint2D(input.target.x, input.target.y)};
    in.maxRobotSpeed = 1.0;
    in.maxObstacleDist = 1.0;
    in.clearance = &clearance;
    mrpt::nav::CAbstractHolonomicReactiveMethod::NavOutput out;
    nd.navigate(in, out);
    const auto log = std::dynamic_pointer_cast<mrpt::nav::CLogFileRecord_ND>(out.logRecord);
    ASSERT_TRUE(log);
    EXPECT_EQ(log->situation, mrpt::nav::CHolonomicND::SITUATION_WIDE_GAP);
    ASSERT_EQ(log->gaps_ini.size(), expected.gaps.size());
    for (std::size_t g = 0; g < expected.gaps.size(); ++g) {
      EXPECT_EQ(static_cast<int>(log->gaps_ini[g]), expected.gaps[g].first);
      EXPECT_EQ(static_cast<int>(log->gaps_end[g]), expected.gaps[g].second);
    }
    EXPECT_EQ(log->selectedSector, expected.selected);
    if (!expected.evaluations.empty()) {
      ASSERT_EQ(log->gaps_eval.size(), expected.evaluations.size());
      for (std::size_t g = 0; g < expected.evaluations.size(); ++g)
        EXPECT_NEAR(log->gaps_eval[g], expected.evaluations[g], 0.0005) << "gap " << g;
    }
  }
}

// Why loops of ND are not proven endless: the same input after different histories gets different answers
// (ND prefers the sector it chose last), where VFF answers it the same whatever came before.
TEST(MrptReactiveNavigatorTest, NdRemembersItsLastChoiceAndVffDoesNot) {
  // Two equal gaps, left and right of a wall straight ahead (east), the target behind the wall.
  std::vector<double> gaps(kReactiveSectors, 0.2);
  for (int k = 0; k < 14; ++k) gaps[k] = 1.0;  // -180°..-110°
  for (int k = 58; k < kReactiveSectors; ++k) gaps[k] = 1.0;  // 110°..180°: the two gaps, mirror images
  std::vector<double> left = gaps;  // open only on the left
  for (int k = 0; k < 14; ++k) left[k] = 0.2;
  std::vector<double> right = gaps;  // open only on the right
  for (int k = 58; k < kReactiveSectors; ++k) right[k] = 0.2;
  const MapPoint target{0.8, 0.0};
  for (const std::string& method : {std::string("ND"), std::string("VFF")}) {
    MrptReactiveNavigator after_left(method);
    after_left.navigate(left, target);
    MrptReactiveNavigator after_right(method);
    after_right.navigate(right, target);
    const double a = after_left.navigate(gaps, target).direction;
    const double b = after_right.navigate(gaps, target).direction;
    if (method == "ND") {
      EXPECT_NE(a, b) << "ND answered the same whatever it chose before";
    } else {
      EXPECT_EQ(a, b);
    }
  }
}

// MRPT's ND called directly, on nothing within range: the goal half the range away in each of the 72 sector
// directions. Heading straight for it is every method's answer (VFF's and FullEval's, checked alike), and ND's
// for 67 of the 72. For the five within two sectors of the ±π seam ND's "straight path" case is not tried
// (CHolonomicND.cpp in 2.5.8, lines 308-321: the target sector must lie in (2, 70)), and its gaps do not wrap
// round (lines 170-184): the open circle is one gap whose two "edges" are the seam, and ND steers to that gap's
// representative sector, 9 sectors inside the edge nearer the target (sector 9, or 62), 7 to 9 sectors (35° to
// 45°) off the target. The seam is where sector 0 begins: straight behind a robot given its scan in its own
// frame, due west on the grid.
TEST(MrptReactiveNavigatorTest, NdTurnsAwayFromAnOpenTargetWithinTwoSectorsOfItsSeam) {
  const double sector = 2 * M_PI / kReactiveSectors;
  for (const std::string method : {"ND", "VFF", "FullEval"}) {
    std::vector<int> turned_away;
    for (int k = 0; k < kReactiveSectors; ++k) {
      const double angle = -M_PI + (k + 0.5) * sector;
      auto navigator = mrpt::nav::CAbstractHolonomicReactiveMethod::Factory("CHolonomic" + method);
      ASSERT_TRUE(navigator) << method;
      mrpt::nav::ClearanceDiagram clearance;
      mrpt::nav::CAbstractHolonomicReactiveMethod::NavInput input;
      input.obstacles.assign(kReactiveSectors, 1.0);
      input.targets = {mrpt::math::TPoint2D(0.5 * std::cos(angle), 0.5 * std::sin(angle))};
      input.maxRobotSpeed = 1.0;
      input.maxObstacleDist = 1.0;
      input.clearance = &clearance;
      mrpt::nav::CAbstractHolonomicReactiveMethod::NavOutput output;
      navigator->navigate(input, output);
      const double off = std::remainder(output.desiredDirection - angle, 2 * M_PI);
      if (std::fabs(off) > 1e-9) {
        turned_away.push_back(k);
        const double representative = -M_PI + ((k < kReactiveSectors / 2 ? 9 : 62) + 0.5) * sector;
        EXPECT_NEAR(std::remainder(output.desiredDirection - representative, 2 * M_PI), 0, 1e-9)
            << method << " sector " << k;
      }
    }
    const std::vector<int> expected = method == "ND" ? std::vector<int>{0, 1, 2, 70, 71} : std::vector<int>{};
    EXPECT_EQ(turned_away, expected) << method;
  }
}

}  // namespace
}  // namespace planners
}  // namespace ppp
