#include "ppp_agents/velocity_command.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace ppp {
namespace agents {

namespace {

/// tan(22.5°): the boundary between a straight and a diagonal move's sector of directions.
const double kDiagonalSlope = std::sqrt(2.0) - 1;

/// Components this close (relative to the larger) are equal: a planner's 45° or 135° comes out of cos and sin
/// a last bit apart, and which of the two that bit favours says nothing about the planner's choice.
constexpr double kTieTolerance = 1e-9;

std::string numberText(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace

CommandedMove commandedMove(const VelocityCommand& c, Connectivity connectivity, double resolution) {
  const std::pair<const char*, double> fields[] = {{"linear.x", c.linear_x},   {"linear.y", c.linear_y},
                                                   {"linear.z", c.linear_z},   {"angular.x", c.angular_x},
                                                   {"angular.y", c.angular_y}, {"angular.z", c.angular_z}};
  for (const auto& [name, value] : fields) {
    if (!std::isfinite(value)) return CommandedMove{Action::Stay, std::string(name) + " is " + numberText(value)};
  }
  const double cells_per_second = std::hypot(c.linear_x, c.linear_y) / resolution;
  if (cells_per_second > kMaxSpeedCellsPerSecond) {
    return CommandedMove{Action::Stay, "a speed of " + numberText(cells_per_second) +
                                           " cells per second (linear.x " + numberText(c.linear_x) + ", linear.y " +
                                           numberText(c.linear_y) + " m/s), more than " +
                                           numberText(kMaxSpeedCellsPerSecond)};
  }
  if (cells_per_second < kStopSpeedCellsPerSecond) return CommandedMove{};
  const double ax = std::abs(c.linear_x);
  const double ay = std::abs(c.linear_y);
  const bool east = c.linear_x > 0;
  const bool north = c.linear_y > 0;
  if (connectivity == Connectivity::Eight && std::min(ax, ay) > kDiagonalSlope * std::max(ax, ay)) {
    if (north) return CommandedMove{east ? Action::NorthEast : Action::NorthWest, ""};
    return CommandedMove{east ? Action::SouthEast : Action::SouthWest, ""};
  }
  if (ax >= ay * (1 - kTieTolerance)) return CommandedMove{east ? Action::East : Action::West, ""};
  return CommandedMove{north ? Action::North : Action::South, ""};
}

}  // namespace agents
}  // namespace ppp
