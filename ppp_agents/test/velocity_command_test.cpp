// The move a local planner's velocity command gives the robot (commandedMove), with the expected moves worked
// out by hand from the command's direction in the map frame (x east, y north).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ppp_agents/velocity_command.hpp"

namespace ppp {
namespace agents {
namespace {

VelocityCommand linear(double x, double y) {
  VelocityCommand command;
  command.linear_x = x;
  command.linear_y = y;
  return command;
}

Action move4(double x, double y) { return commandedMove(linear(x, y), Connectivity::Four, 1.0).action; }
Action move8(double x, double y) { return commandedMove(linear(x, y), Connectivity::Eight, 1.0).action; }

TEST(CommandedMove, FourConnectedTakesTheAxisOfTheLargerComponent) {
  EXPECT_EQ(move4(1, 0), Action::East);
  EXPECT_EQ(move4(-1, 0), Action::West);
  EXPECT_EQ(move4(0, 1), Action::North);  // map y points north (towards grid row 0)
  EXPECT_EQ(move4(0, -1), Action::South);
  EXPECT_EQ(move4(0.6, -0.8), Action::South);
  EXPECT_EQ(move4(-0.8, 0.6), Action::West);
  EXPECT_EQ(move4(0.5, 0.5), Action::East);    // a tie goes to the x move
  EXPECT_EQ(move4(-0.5, -0.5), Action::West);
  // A diagonal through cos and sin is a tie too, whichever way the last bit falls: |sin 135°| is one bit more
  // than |cos 135°|.
  const double diagonal = 3 * M_PI / 4;
  ASSERT_GT(std::fabs(std::sin(diagonal)), std::fabs(std::cos(diagonal)));
  EXPECT_EQ(move4(std::cos(diagonal), std::sin(diagonal)), Action::West);
  EXPECT_EQ(move4(std::cos(-diagonal), std::sin(-diagonal)), Action::West);
  EXPECT_EQ(move4(std::cos(M_PI / 4), std::sin(M_PI / 4)), Action::East);
  EXPECT_EQ(move4(std::cos(-M_PI / 4), std::sin(-M_PI / 4)), Action::East);
  // Beyond the tolerance the larger component wins.
  EXPECT_EQ(move4(1, 1 + 1e-6), Action::North);
  EXPECT_EQ(move4(-1 - 1e-6, 1), Action::West);
}

TEST(CommandedMove, EightConnectedTakesADiagonalInsideItsSector) {
  EXPECT_EQ(move8(1, 1), Action::NorthEast);
  EXPECT_EQ(move8(-1, 1), Action::NorthWest);
  EXPECT_EQ(move8(-1, -1), Action::SouthWest);
  EXPECT_EQ(move8(1, -1), Action::SouthEast);
  // 22.5° from the x axis is the boundary: just inside it a straight move, just beyond a diagonal.
  const double boundary = std::tan(M_PI / 8);
  EXPECT_EQ(move8(1, boundary * 0.999), Action::East);
  EXPECT_EQ(move8(1, boundary * 1.001), Action::NorthEast);
  EXPECT_EQ(move8(-boundary * 1.001, -1), Action::SouthWest);
  EXPECT_EQ(move8(-boundary * 0.999, -1), Action::South);
  EXPECT_EQ(move8(0, 2), Action::North);
}

TEST(CommandedMove, SlowCommandsStayAndSpeedIsInCellsPerSecond) {
  EXPECT_EQ(move4(0, 0), Action::Stay);
  EXPECT_EQ(move4(0.009, 0), Action::Stay);
  EXPECT_EQ(move4(0.011, 0), Action::East);
  // With 0.1 m cells, 0.002 m/s is 0.02 cells per second: a move; with 1 m cells it is not.
  EXPECT_EQ(commandedMove(linear(0, 0.002), Connectivity::Four, 0.1).action, Action::North);
  EXPECT_EQ(commandedMove(linear(0, 0.002), Connectivity::Four, 1.0).action, Action::Stay);
  // Turning and climbing are ignored: the robot's frame stays aligned with the map.
  VelocityCommand turning = linear(0, -1);
  turning.angular_z = 3;
  turning.linear_z = 2;
  EXPECT_EQ(commandedMove(turning, Connectivity::Four, 1.0).action, Action::South);
  EXPECT_TRUE(commandedMove(turning, Connectivity::Four, 1.0).problem.empty());
}

TEST(CommandedMove, NamesTheFieldThatIsNotANumber) {
  VelocityCommand command = linear(1, 0);
  command.linear_y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(commandedMove(command, Connectivity::Four, 1.0).problem, "linear.y is nan");
  command = linear(1, 0);
  command.angular_z = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(commandedMove(command, Connectivity::Four, 1.0).problem, "angular.z is -inf");
}

TEST(CommandedMove, RefusesAbsurdSpeeds) {
  EXPECT_TRUE(commandedMove(linear(999, 0), Connectivity::Four, 1.0).problem.empty());
  EXPECT_TRUE(commandedMove(linear(600, 800), Connectivity::Four, 1.0).problem.empty());  // exactly 1000
  EXPECT_EQ(commandedMove(linear(1200, -1600), Connectivity::Four, 1.0).problem,
            "a speed of 2000 cells per second (linear.x 1200, linear.y -1600 m/s), more than 1000");
  EXPECT_EQ(commandedMove(linear(0, 2000), Connectivity::Four, 1.0).problem,
            "a speed of 2000 cells per second (linear.x 0, linear.y 2000 m/s), more than 1000");
  // 150 m/s is 1500 cells per second of 0.1 m.
  EXPECT_FALSE(commandedMove(linear(150, 0), Connectivity::Four, 0.1).problem.empty());
}

}  // namespace
}  // namespace agents
}  // namespace ppp
