#include "sector_obstacles.hpp"

#include <algorithm>
#include <cmath>

namespace ppp {
namespace planners {

namespace {

/// Radians per sector.
constexpr double kSectorWidth = 2 * M_PI / kReactiveSectors;

/// Calls `visit(sector)` for the sector a ray at `angle` (radians, any turn) lies in, and for its neighbour too
/// when the ray lies on their border. LaserScan's angles are floats: its rays come out up to 2e-6 sector widths
/// off the borders they lie on, so a tighter tolerance would put them in one sector only, and a planner would see
/// another scan through ROS than the same rays in double precision.
template <typename Visit>
void forSectorsOfRay(double angle, Visit visit) {
  const double place = (std::remainder(angle, 2 * M_PI) + M_PI) / kSectorWidth;  // from -π, counter-clockwise
  const int sector = static_cast<int>(std::floor(place)) % kReactiveSectors;
  visit(sector);
  const double offset = place - std::floor(place);
  constexpr double kBorder = 1e-3;  // sector widths
  if (offset < kBorder) visit((sector + kReactiveSectors - 1) % kReactiveSectors);
  if (offset > 1 - kBorder) visit((sector + 1) % kReactiveSectors);
}

/// Metres a disc of `radius` at the origin travels along the unit direction (ux, uy) before it touches the point
/// (px, py); +inf when it never does. A point already inside the disc gives 0 when the direction goes deeper
/// into it (the disc would leave it only after travelling at least its radius) and +inf when it leaves it.
double discTravel(double px, double py, double ux, double uy, double radius) {
  const double along = px * ux + py * uy;
  const double across = px * uy - py * ux;
  if (std::abs(across) >= radius) return INFINITY;
  const double half_chord = std::sqrt(radius * radius - across * across);
  if (px * px + py * py > radius * radius) return along - half_chord >= 0 ? along - half_chord : INFINITY;
  return along + half_chord < radius ? INFINITY : 0.0;
}

/// True when a disc of `radius` metres at `centre` overlaps a cell of `map` that is not passable.
bool discBlocked(const GridMap& map, MapPoint centre, double radius) {
  const MapFrame& frame = map.frame();
  const double r = frame.resolution;
  // Map-frame columns and rows (x east, y north, from the map's origin) the disc's bounding box spans.
  const int first_column = static_cast<int>(std::floor((centre.x - radius) / r));
  const int last_column = static_cast<int>(std::floor((centre.x + radius) / r));
  const int first_row = static_cast<int>(std::floor((centre.y - radius) / r));
  const int last_row = static_cast<int>(std::floor((centre.y + radius) / r));
  for (int row = first_row; row <= last_row; ++row) {
    for (int column = first_column; column <= last_column; ++column) {
      const Cell cell = frame.cellOfMapRowColumn(column, row);
      if (map.passable(cell)) continue;
      const double dx = centre.x - std::clamp(centre.x, column * r, (column + 1) * r);
      const double dy = centre.y - std::clamp(centre.y, row * r, (row + 1) * r);
      if (dx * dx + dy * dy < radius * radius) return true;
    }
  }
  return false;
}

}  // namespace

double sectorAngle(int k) { return -M_PI + (k + 0.5) * kSectorWidth; }

std::vector<double> sectorObstacles(const LaserRays& scan, double range, int* invalid_rays) {
  std::vector<double> obstacles(kReactiveSectors, 1.0);
  *invalid_rays = 0;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    double distance = scan.ranges[i];
    if (std::isnan(distance)) {
      ++*invalid_rays;
      distance = 0;
    }
    const double fraction = std::clamp(distance / range, 0.0, 1.0);
    forSectorsOfRay(scan.angle_min + i * scan.angle_increment,
                    [&](int sector) { obstacles[sector] = std::min(obstacles[sector], fraction); });
  }
  return obstacles;
}

std::vector<double> sectorObstaclesForDisc(const LaserRays& scan, double range, double radius, int* invalid_rays) {
  std::vector<double> travel(kReactiveSectors, INFINITY);
  std::vector<double> east(kReactiveSectors), north(kReactiveSectors);
  for (int k = 0; k < kReactiveSectors; ++k) {
    east[k] = std::cos(sectorAngle(k));
    north[k] = std::sin(sectorAngle(k));
  }
  *invalid_rays = 0;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double distance = scan.ranges[i];
    const double angle = scan.angle_min + i * scan.angle_increment;
    if (std::isnan(distance)) {
      ++*invalid_rays;
      forSectorsOfRay(angle, [&](int sector) { travel[sector] = 0; });
      continue;
    }
    if (!std::isfinite(distance)) continue;  // no return within the laser's range
    const double px = distance * std::cos(angle);
    const double py = distance * std::sin(angle);
    for (int k = 0; k < kReactiveSectors; ++k) {
      travel[k] = std::min(travel[k], discTravel(px, py, east[k], north[k], radius));
    }
  }
  std::vector<double> obstacles(kReactiveSectors);
  for (int k = 0; k < kReactiveSectors; ++k) obstacles[k] = std::clamp(travel[k] / range, 0.0, 1.0);
  return obstacles;
}

std::vector<double> sectorObstaclesInMap(const GridMap& map, MapPoint from, double heading, double range,
                                         double radius) {
  std::vector<double> obstacles(kReactiveSectors, 1.0);
  const double step = map.frame().resolution / 8;
  for (int k = 0; k < kReactiveSectors; ++k) {
    const double east = std::cos(heading + sectorAngle(k));
    const double north = std::sin(heading + sectorAngle(k));
    for (double t = step; t <= range; t += step) {
      const MapPoint centre{from.x + east * t, from.y + north * t};
      if (radius > 0 ? discBlocked(map, centre, radius) : !map.passable(map.cellOf(centre))) {
        obstacles[k] = t / range;
        break;
      }
    }
  }
  return obstacles;
}

}  // namespace planners
}  // namespace ppp
