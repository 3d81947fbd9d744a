#pragma once

#include <string>

#include "ppp_core/action.hpp"
#include "ppp_core/connectivity.hpp"

namespace ppp {
namespace agents {

/// A local planner's velocity command (geometry_msgs/Twist's six numbers) in the robot's frame, which is aligned
/// with the map's and never turns: linear x points east, linear y north, in metres per second.
struct VelocityCommand {
  double linear_x = 0, linear_y = 0, linear_z = 0;     ///< Metres per second.
  double angular_x = 0, angular_y = 0, angular_z = 0;  ///< Radians per second (ignored: the robot never turns).
};

/// Below this many PPP cells per second the robot stays.
constexpr double kStopSpeedCellsPerSecond = 0.01;
/// Above this many PPP cells per second a command is refused as absurd.
constexpr double kMaxSpeedCellsPerSecond = 1000;

/// The move a velocity command asks for, or what is wrong with it.
struct CommandedMove {
  Action action = Action::Stay;  ///< The move nearest the command's direction (Stay when slower than the stop speed).
  std::string problem;           ///< Non-empty when the command is unusable: names the field and its value.
};

/// The move nearest the direction of (linear_x, linear_y): with Connectivity::Four the axis of the larger
/// component (x on a tie, components within a relative 1e-9 being tied); with Eight a diagonal when the smaller
/// component is more than tan(22.5°) of the larger, else that axis. Stays below kStopSpeedCellsPerSecond
/// (`resolution` metres per cell); a command with a number that is not finite, or faster than
/// kMaxSpeedCellsPerSecond, is a problem.
CommandedMove commandedMove(const VelocityCommand& command, Connectivity connectivity, double resolution);

}  // namespace agents
}  // namespace ppp
