#include "ppp_core/barn_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "ppp_core/dpa.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {

namespace {

constexpr double kPi = 3.14159265358979323846;
/// Direction components smaller than this are exact zeros (cos(pi/2) is 6e-17 in doubles).
constexpr double kZeroComponent = 1e-12;
/// Two boundary crossings closer than this (relative) are one crossing through a cell corner.
constexpr double kCornerTolerance = 1e-9;

/// A unit direction in grid coordinates (x right, y down).
struct Direction {
  double dx = 0;
  double dy = 0;
};

/// The n directions at 2*pi*i/n counter-clockwise from east, north being row - 1.
std::vector<Direction> circleOf(int n) {
  auto snap = [](double v) { return std::abs(v) < kZeroComponent ? 0.0 : v; };
  std::vector<Direction> directions;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * kPi * i / n;
    directions.push_back({snap(std::cos(angle)), snap(-std::sin(angle))});
  }
  return directions;
}

/// Distance from the centre of `from` along `d` to where the ray enters the interior of an obstacle cell or leaves
/// the grid, at most `limit`. A ray through a cell corner goes straight into the diagonal cell.
double rayLength(const Grid& grid, Cell from, Direction d, double limit) {
  const double infinity = std::numeric_limits<double>::infinity();
  const double step_x = d.dx != 0 ? 1 / std::abs(d.dx) : infinity;
  const double step_y = d.dy != 0 ? 1 / std::abs(d.dy) : infinity;
  double next_x = step_x / 2;
  double next_y = step_y / 2;
  Cell cell = from;
  for (;;) {
    const double t = std::min(next_x, next_y);
    if (t >= limit) return limit;
    const bool corner = std::abs(next_x - next_y) <= kCornerTolerance * t;
    const bool cross_x = corner || next_x < next_y;
    const bool cross_y = corner || next_y < next_x;
    if (cross_x) {
      cell.x += d.dx > 0 ? 1 : -1;
      next_x += step_x;
    }
    if (cross_y) {
      cell.y += d.dy > 0 ? 1 : -1;
      next_y += step_y;
    }
    if (!grid.isFree(cell)) return t;
  }
}

/// Per cell, rows to the nearest blocked cell of its column (an obstacle, or the rows beyond the edges); 0 on one.
std::vector<int> columnGaps(const Grid& grid) {
  std::vector<int> gaps(static_cast<std::size_t>(grid.size()));
  for (int x = 0; x < grid.width(); ++x) {
    int blocked = -1;
    for (int y = 0; y < grid.height(); ++y) {
      if (grid.isObstacle({x, y})) blocked = y;
      gaps[static_cast<std::size_t>(grid.index({x, y}))] = y - blocked;
    }
    blocked = grid.height();
    for (int y = grid.height() - 1; y >= 0; --y) {
      if (grid.isObstacle({x, y})) blocked = y;
      int& gap = gaps[static_cast<std::size_t>(grid.index({x, y}))];
      gap = std::min(gap, blocked - y);
    }
  }
  return gaps;
}

/// Distance from a cell's centre to the nearest point of the cell `offset` rows (or columns) away; 0 for itself.
double sideDistance(int offset) { return std::max(0.0, std::abs(offset) - 0.5); }

/// Distance from the centre of `cell` to the nearest obstacle cell or grid edge, at most `limit`: the nearest
/// blocked cell of each column, columns taken outwards until they are farther than the best so far.
double clearance(const Grid& grid, const std::vector<int>& gaps, Cell cell, double limit) {
  double best = std::min({limit, sideDistance(cell.x + 1), sideDistance(grid.width() - cell.x)});
  for (int offset = 0; sideDistance(offset) < best; ++offset) {
    for (int x : {cell.x - offset, cell.x + offset}) {
      if (x < 0 || x >= grid.width()) continue;
      const int gap = gaps[static_cast<std::size_t>(grid.index({x, cell.y}))];
      best = std::min(best, std::hypot(sideDistance(offset), sideDistance(gap)));
    }
  }
  return best;
}

/// Mean length of the rays from `cell`, each at most `limit`.
double meanRayLength(const Grid& grid, Cell cell, const std::vector<Direction>& rays, double limit) {
  double total = 0;
  for (const Direction& d : rays) total += rayLength(grid, cell, d, limit);
  return total / static_cast<double>(rays.size());
}

/// Changes between blocked (shorter than `radius`) and open rays, going once around the circle of rays.
int alternations(const Grid& grid, Cell cell, const std::vector<Direction>& rays, double radius) {
  std::vector<bool> blocked;
  for (const Direction& d : rays) blocked.push_back(rayLength(grid, cell, d, radius) < radius);
  int changes = 0;
  for (std::size_t i = 0; i < blocked.size(); ++i) changes += blocked[i] != blocked[(i + 1) % blocked.size()];
  return changes;
}

/// Shortest free chord through the centre of `cell` along the axes (each half at most `limit`).
double narrowestChord(const Grid& grid, Cell cell, const std::vector<Direction>& axes, double limit) {
  double narrowest = std::numeric_limits<double>::infinity();
  for (const Direction& d : axes) {
    const double chord = rayLength(grid, cell, d, limit) + rayLength(grid, cell, {-d.dx, -d.dy}, limit);
    narrowest = std::min(narrowest, chord);
  }
  return narrowest;
}

/// Straight-line distance between two cell centres.
double centreDistance(Cell a, Cell b) { return std::hypot(a.x - b.x, a.y - b.y); }

/// @throws InvalidArgument naming "route" unless it has two or more free cells on the grid and distinct ends.
void checkRoute(const Grid& grid, const std::vector<Cell>& route) {
  if (route.size() < 2) throw InvalidArgument("route", "needs two or more cells, got " + std::to_string(route.size()));
  for (const Cell& c : route) {
    if (!grid.isFree(c)) {
      throw InvalidArgument("route", "cell " + cellText(c) + " is off the grid or an obstacle");
    }
  }
  if (route.front() == route.back()) throw InvalidArgument("route", "ends where it starts; tortuosity needs a chord");
}

}  // namespace

void BarnOptions::validate() const {
  const std::pair<const char*, int> counts[] = {
      {"visibility_rays", visibility_rays}, {"dispersion_rays", dispersion_rays}, {"dimension_axes", dimension_axes}};
  for (const auto& [name, count] : counts) {
    if (count < 1 || count > kMaxBarnRays) {
      throw InvalidArgument(name, "must be in [1, " + std::to_string(kMaxBarnRays) + "], got " + std::to_string(count));
    }
  }
  if (!(dispersion_radius > 0) || std::isinf(dispersion_radius)) {
    throw InvalidArgument("dispersion_radius",
                          "must be a positive number of cells, got " + formatShortest(dispersion_radius));
  }
  if (!(range > 0)) {
    throw InvalidArgument("range", "must be positive (cells; infinite for no limit), got " + formatShortest(range));
  }
}

BarnMetrics barnMetrics(const Grid& grid, const std::vector<Cell>& route, const BarnOptions& options) {
  options.validate();
  checkRoute(grid, route);
  const std::vector<Direction> visibility_rays = circleOf(options.visibility_rays);
  const std::vector<Direction> dispersion_rays = circleOf(options.dispersion_rays);
  std::vector<Direction> axes = circleOf(2 * options.dimension_axes);
  axes.resize(static_cast<std::size_t>(options.dimension_axes));
  const double radius = std::min(options.dispersion_radius, options.range);
  const std::vector<int> gaps = columnGaps(grid);
  BarnMetrics m;
  m.valid = true;
  double length = 0;
  for (std::size_t i = 0; i < route.size(); ++i) {
    const Cell cell = route[i];
    m.closest_obstacle += clearance(grid, gaps, cell, options.range);
    m.visibility += meanRayLength(grid, cell, visibility_rays, options.range);
    m.dispersion += alternations(grid, cell, dispersion_rays, radius);
    m.characteristic_dimension += narrowestChord(grid, cell, axes, options.range);
    if (i > 0) length += centreDistance(route[i - 1], cell);
  }
  const double cells = static_cast<double>(route.size());
  m.closest_obstacle /= cells;
  m.visibility /= cells;
  m.dispersion /= cells;
  m.characteristic_dimension /= cells;
  m.tortuosity = length / centreDistance(route.front(), route.back());
  return m;
}

BarnMetrics barnMetrics(const Grid& grid, const DpaResult& dpa, const BarnOptions& options) {
  options.validate();
  if (!dpa.reachable) return BarnMetrics{};
  return barnMetrics(grid, dpa.route, options);
}

BarnMetrics barnMetrics(const Problem& problem, const Grid& grid, const BarnOptions& options) {
  return barnMetrics(grid, solveDpa(grid, problem.start, problem.goal), options);
}

const std::vector<std::string>& barnCharacterNames() {
  static const std::vector<std::string> names = {"barn_closest_obstacle", "barn_visibility", "barn_dispersion",
                                                 "barn_characteristic_dimension", "barn_tortuosity"};
  return names;
}

std::vector<double> barnCharacterVector(const BarnMetrics& m) {
  return {m.closest_obstacle, m.visibility, m.dispersion, m.characteristic_dimension, m.tortuosity};
}

}  // namespace ppp
