#include "ppp_agents/continuous/laser_memory.hpp"

#include <cmath>
#include <limits>

#include "ppp_core/sensor.hpp"

namespace ppp {
namespace agents {

namespace {

/// Fraction of a cell a return's point is moved along its beam to fall inside the square it met (far above a
/// float range's rounding, far below a cell).
constexpr double kBeyondReturn = 1e-4;

/// True when `v` (in cells) is within `tolerance` of a whole number.
bool nearGridLine(double v, double tolerance) { return std::fabs(v - std::round(v)) <= tolerance; }

}  // namespace

void LaserMemory::start(const MapFrame& frame, const Pose2D& start) {
  frame_ = frame;
  cells_.assign(static_cast<std::size_t>(frame.width) * frame.height, kScanUnknown);
  const int column = static_cast<int>(std::floor(start.x / frame.resolution));
  const int row = static_cast<int>(std::floor(start.y / frame.resolution));
  if (onMap(column, row)) cells_[index(column, row)] = kScanFree;
}

bool LaserMemory::add(const Pose2D& pose, const std::vector<float>& ranges, const LaserBeams& beams) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const double eps = kBeyondReturn * frame_.resolution;
  bool changed = false;
  for (std::size_t i = 0; i < ranges.size() && i < beams.cosines.size(); ++i) {
    const double dx = c * beams.cosines[i] - s * beams.sines[i];
    const double dy = s * beams.cosines[i] + c * beams.sines[i];
    const double range = ranges[i];
    if (std::isnan(range)) continue;
    const bool returned = std::isfinite(range);
    changed |= markCrossed(pose.x, pose.y, dx, dy, returned ? range - eps : beams.range_max);
    if (returned) changed |= markReturn(pose.x + range * dx, pose.y + range * dy, dx, dy);
  }
  return changed;
}

bool LaserMemory::markCrossed(double x, double y, double dx, double dy, double length) {
  const double res = frame_.resolution;
  int column = static_cast<int>(std::floor(x / res));
  int row = static_cast<int>(std::floor(y / res));
  const double inf = std::numeric_limits<double>::infinity();
  // Amanatides & Woo: the distance along the beam to the next column and row boundary, and between boundaries.
  const int step_column = dx > 0 ? 1 : -1, step_row = dy > 0 ? 1 : -1;
  double next_column = dx > 0 ? ((column + 1) * res - x) / dx : dx < 0 ? (column * res - x) / dx : inf;
  double next_row = dy > 0 ? ((row + 1) * res - y) / dy : dy < 0 ? (row * res - y) / dy : inf;
  const double delta_column = dx != 0 ? res / std::fabs(dx) : inf;
  const double delta_row = dy != 0 ? res / std::fabs(dy) : inf;
  bool changed = false;
  while (onMap(column, row)) {
    std::int8_t& cell = cells_[index(column, row)];
    if (cell == kScanUnknown) cell = kScanFree, changed = true;
    const double next = std::min(next_column, next_row);
    if (next > length) break;
    // Through a corner the beam passes diagonally: the two cells beside it hold only the corner point.
    if (next_column <= next) column += step_column, next_column += delta_column;
    if (next_row <= next) row += step_row, next_row += delta_row;
  }
  return changed;
}

bool LaserMemory::markReturn(double x, double y, double dx, double dy) {
  const double res = frame_.resolution;
  if (nearGridLine(x / res, kCornerTolerance) && nearGridLine(y / res, kCornerTolerance)) return false;
  const double eps = kBeyondReturn * res;
  const int column = static_cast<int>(std::floor((x + eps * dx) / res));
  const int row = static_cast<int>(std::floor((y + eps * dy) / res));
  if (!onMap(column, row)) return false;  // the border
  std::int8_t& cell = cells_[index(column, row)];
  if (cell == kScanObstacle) return false;
  cell = kScanObstacle;
  return true;
}

}  // namespace agents
}  // namespace ppp
