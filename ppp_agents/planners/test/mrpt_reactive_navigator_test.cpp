// MRPT's holonomic reactive navigators driven as mrpt_reactive_node drives them, without ROS: obstacle distances
// per direction from the robot's scan, the goal relative to the robot, a direction and speed out, and the robot
// taking the 4-connected move nearest that direction (ppp_agents' commandedMove), as the planner bridge does.
#include "mrpt_reactive_navigator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "map_picture.hpp"
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

/// The robot's walk on a drawn map ('#' obstacles, S start, G goal; 1 m cells): at each step the range-2 scan
/// as the bridge's 72 rays, normalised by the scan's range, and the goal relative to the robot go to the method;
/// the robot takes the move nearest its direction. Stops on the goal or after `steps` steps.
std::vector<Choice> walk(const Picture& picture, const std::string& method, int steps) {
  const Grid grid = test::pictureGrid(picture);
  const Cell goal = test::markedCell(picture, 'G');
  const MapFrame frame{grid.width(), grid.height(), 1.0};
  const SensorModel sensor(SensorOptions{2, 0.0});
  MrptReactiveNavigator navigator(method);
  Cell robot = test::markedCell(picture, 'S');
  std::vector<Choice> choices;
  for (int step = 0; step < steps && !(robot == goal); ++step) {
    std::vector<std::int8_t> window(25);
    sensor.see(grid, robot, window.data());
    int invalid = 0;
    const std::vector<double> obstacles =
        sectorObstacles(LaserRays{0, 2 * M_PI / kRays, windowRanges(window.data(), 2, kRays)}, kScanRange, &invalid);
    const MapPoint target{(frame.centreX(goal) - frame.centreX(robot)) / kScanRange,
                          (frame.centreY(goal) - frame.centreY(robot)) / kScanRange};
    const Heading heading = navigator.navigate(obstacles, target);
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

// Sector k spans [-180° + 5k, -175° + 5k]: a ray at 0° lies on the border of sectors 35 and 36 and counts for
// both; one at 92° lies inside sector 54 ([90°, 95°]) alone.
TEST(MrptReactiveNavigatorTest, ScanRaysBecomeSectorDistancesAsFractionsOfTheRange) {
  std::vector<float> ranges(kRays, std::numeric_limits<float>::infinity());
  ranges[0] = 1.0f;  // 0°
  ranges[18] = 0.5f;  // 90°: the border of sectors 53 and 54
  LaserRays scan{0, 2 * M_PI / kRays, ranges};
  int invalid = -1;
  std::vector<double> sectors = sectorObstacles(scan, 2.0, &invalid);
  EXPECT_EQ(invalid, 0);
  EXPECT_DOUBLE_EQ(sectors[35], 0.5);
  EXPECT_DOUBLE_EQ(sectors[36], 0.5);
  EXPECT_DOUBLE_EQ(sectors[53], 0.25);
  EXPECT_DOUBLE_EQ(sectors[54], 0.25);
  EXPECT_DOUBLE_EQ(sectors[37], 1.0);  // +inf: nothing within range
  EXPECT_DOUBLE_EQ(sectors[0], 1.0);
  // Rays rotated by 2°: each lies inside one sector.
  scan.angle_min = 2 * M_PI / 180;
  sectors = sectorObstacles(scan, 2.0, &invalid);
  EXPECT_DOUBLE_EQ(sectors[36], 0.5);
  EXPECT_DOUBLE_EQ(sectors[35], 1.0);
  EXPECT_DOUBLE_EQ(sectors[54], 0.25);
  // A NaN ray is no reading: taken as an obstacle at the robot, and counted.
  scan.angle_min = 0;
  scan.ranges[36] = std::numeric_limits<float>::quiet_NaN();  // 180°: the border of sectors 71 and 0
  sectors = sectorObstacles(scan, 2.0, &invalid);
  EXPECT_EQ(invalid, 1);
  EXPECT_DOUBLE_EQ(sectors[0], 0.0);
  EXPECT_DOUBLE_EQ(sectors[71], 0.0);
  // Beyond the range a distance is 1.
  scan.ranges[0] = 7.0f;
  sectors = sectorObstacles(scan, 2.0, &invalid);
  EXPECT_DOUBLE_EQ(sectors[36], 1.0);
}

// Cast on a known map: from the centre of cell (1, 1) of a 4x3 map of 1 m cells, east meets the wall at x = 3
// (1.5 m), west the map's edge (1.5 m), north the edge (1.5 m from y = 1.5 to 3... the top row is free).
TEST(MrptReactiveNavigatorTest, MapCastsEndAtKnownObstaclesAndTheMapsEdge) {
  const GridMap map = test::mapPicture({"....", ".S.#", "...."});
  const MapPoint robot = map.centre(Cell{1, 1});
  const std::vector<double> sectors = sectorObstaclesInMap(map, robot, 3.0);
  // Sector 36 is centred at 2.5°, so its ray meets x = 3 at 1.5 / cos 2.5° m; sector 71 (177.5°) meets x = 0
  // after 1.5 / cos 2.5° m; sector 54 (92.5°) meets y = 3 after 1.5 / cos 2.5° m.
  const double along = 1.5 / std::cos(2.5 * M_PI / 180) / 3.0;
  const double step = 1.0 / 8 / 3.0;  // the cast's resolution, as a fraction of the range
  EXPECT_NEAR(sectors[36], along, step);
  EXPECT_NEAR(sectors[71], along, step);
  EXPECT_NEAR(sectors[54], along, step);
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
  const Picture corner = {"S.......", "........", "........", "........",
                          "........", "........", "........", ".......G"};
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
  const Picture trap = {
      "....G....",
      ".........",
      "..#####..",
      "..#...#..",
      "..#.S.#..",
      "..#...#..",
      ".........",
  };
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
      if (method == "VFF") EXPECT_NEAR(std::fabs(choices[i].degrees), 90.0, 1e-9) << "step " << i;
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

}  // namespace
}  // namespace planners
}  // namespace ppp
