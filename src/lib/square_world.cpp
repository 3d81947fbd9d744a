#include "ppp_core/square_world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ppp {

namespace {

/// The distance along the unit vector (dx, dy) from `origin` to the first blocked cell of `blocked` (rows of
/// `stride` cells of `res` metres), or +infinity beyond `max_range`: the grid traversal of Amanatides and Woo
/// (1987), stepping from cell boundary to cell boundary, the nearer of the next vertical and horizontal one each
/// time. Always inlined: with castRay() as a second caller GCC stopped inlining it into castFan(), whose scans took
/// a third longer (laser_bench).
[[gnu::always_inline]] inline double traverse(const std::uint8_t* blocked, int stride, double res,
                                              const SquareWorld::Origin& origin, double dx, double dy,
                                              double max_range) {
  // A direction component below kAlongAxis counts as kAlongAxis: the ray then crosses that axis's boundaries only
  // a million kilometres away, and the arithmetic below never meets an infinity.
  constexpr double kAlongAxis = 1e-12;
  const double inverse_x = 1 / std::max(std::fabs(dx), kAlongAxis);
  const double inverse_y = 1 / std::max(std::fabs(dy), kAlongAxis);
  double next_x = (dx > 0 ? origin.right : origin.left) * inverse_x;
  double next_y = (dy > 0 ? origin.up : origin.down) * inverse_y;
  const double delta_x = res * inverse_x, delta_y = res * inverse_y;
  const int step_x = dx > 0 ? 1 : -1, step_y = dy > 0 ? stride : -stride;
  int index = origin.index;
  for (;;) {
    double t;
    if (next_x < next_y) {
      t = next_x;
      index += step_x;
      next_x += delta_x;
    } else {
      t = next_y;
      index += step_y;
      next_y += delta_y;
    }
    if (t > max_range) return std::numeric_limits<double>::infinity();
    if (blocked[index] != 0) return t;
  }
}

}  // namespace


SquareWorld::SquareWorld(const Grid& grid, double resolution)
    : frame_{grid.width(), grid.height(), resolution},
      stride_(grid.width() + 2),
      blocked_(static_cast<std::size_t>(grid.width() + 2) * (grid.height() + 2), 1) {
  for (int row = 0; row < frame_.height; ++row) {
    for (int column = 0; column < frame_.width; ++column) {
      blocked_[(row + 1) * stride_ + column + 1] = grid.isObstacle(frame_.cellOfMapRowColumn(column, row)) ? 1 : 0;
    }
  }
}

Cell SquareWorld::cellAt(double x, double y) const {
  const int column = static_cast<int>(std::floor(x / frame_.resolution));
  const int row = static_cast<int>(std::floor(y / frame_.resolution));
  return frame_.cellOfMapRowColumn(column, row);
}

double SquareWorld::clearance(double x, double y, double cap) const {
  const double res = frame_.resolution;
  double best = std::min({cap, x, widthMetres() - x, y, heightMetres() - y});
  if (best <= 0) return 0;
  const int c0 = std::max(0, static_cast<int>(std::floor((x - best) / res)));
  const int c1 = std::min(frame_.width - 1, static_cast<int>(std::floor((x + best) / res)));
  const int r0 = std::max(0, static_cast<int>(std::floor((y - best) / res)));
  const int r1 = std::min(frame_.height - 1, static_cast<int>(std::floor((y + best) / res)));
  for (int row = r0; row <= r1; ++row) {
    const double dy = std::max({row * res - y, 0.0, y - (row + 1) * res});
    if (dy >= best) continue;
    for (int column = c0; column <= c1; ++column) {
      if (!blocked(column, row)) continue;
      const double dx = std::max({column * res - x, 0.0, x - (column + 1) * res});
      best = std::min(best, std::hypot(dx, dy));
    }
  }
  return best;
}

double SquareWorld::castRay(double x, double y, double angle, double max_range) const {
  const Origin origin = originAt(x, y);
  return origin.index < 0 ? 0
                          : traverse(blocked_.data(), stride_, frame_.resolution, origin, std::cos(angle),
                                     std::sin(angle), max_range);
}

void SquareWorld::castFan(double x, double y, double turn_cos, double turn_sin, const std::vector<double>& cosines,
                          const std::vector<double>& sines, double max_range, float* ranges) const {
  const Origin origin = originAt(x, y);
  if (origin.index < 0) {
    std::fill(ranges, ranges + cosines.size(), 0.0f);
    return;
  }
  const std::uint8_t* blocked = blocked_.data();
  const int stride = stride_;
  const double res = frame_.resolution;
  for (std::size_t i = 0; i < cosines.size(); ++i) {
    const double dx = turn_cos * cosines[i] - turn_sin * sines[i];
    const double dy = turn_sin * cosines[i] + turn_cos * sines[i];
    ranges[i] = static_cast<float>(traverse(blocked, stride, res, origin, dx, dy, max_range));
  }
}

SquareWorld::Origin SquareWorld::originAt(double x, double y) const {
  const double res = frame_.resolution;
  Origin origin;
  if (!(x >= 0 && y >= 0 && x < widthMetres() && y < heightMetres())) return origin;
  const int column = static_cast<int>(x / res), row = static_cast<int>(y / res);
  if (blocked(column, row)) return origin;
  origin.index = (row + 1) * stride_ + column + 1;
  origin.right = (column + 1) * res - x;
  origin.left = x - column * res;
  origin.up = (row + 1) * res - y;
  origin.down = y - row * res;
  return origin;
}

}  // namespace ppp
