#pragma once

#include <vector>

#include "grid_map.hpp"
#include "ppp_core/map_frame.hpp"

namespace ppp {
namespace planners {

/// The directions obstacles are given in to MRPT's holonomic methods: sector k is centred at
/// sectorAngle(k) = -π + (k + ½)·2π/kReactiveSectors in the robot's frame (MRPT's convention: the first sector
/// points backwards, counter-clockwise from there).
constexpr int kReactiveSectors = 72;

/// Radians of sector k's centre, in [-π, π].
double sectorAngle(int k);

/// A laser scan as sensor_msgs/LaserScan gives it, in the robot's frame.
struct LaserRays {
  double angle_min = 0;        ///< Radians of the first ray, counter-clockwise from the robot's x axis.
  double angle_increment = 0;  ///< Radians between rays.
  std::vector<float> ranges;   ///< Metres; +inf: no return within range, NaN: no valid reading.
};

/// Distances to obstacles per sector for a point robot, as fractions of `range` metres (1: nothing nearer): the
/// nearest ray that lies in a sector (a ray on the border of two counts for both); a sector no ray falls in sees
/// nothing. A ray that is NaN is taken as an obstacle touching the robot (0) and counted in `*invalid_rays`.
std::vector<double> sectorObstacles(const LaserRays& scan, double range, int* invalid_rays);

/// Distances to obstacles per sector for a disc of `radius` metres centred on the laser, as fractions of
/// `range` metres (1: nothing nearer), as MRPT's reactive navigator gives them to a holonomic method (its
/// straight trajectories for a round robot at rest, CPTG_Holo_Blend): how far the disc travels along each
/// sector's centre direction before it touches a return. A return already inside the disc stops (0) each direction
/// along which the disc would leave it only after travelling at least its radius, and no other (MRPT's default
/// collision behaviour, "back away"). A ray
/// that is NaN gives 0 in its sector, as for a point, and is counted in `*invalid_rays`.
std::vector<double> sectorObstaclesForDisc(const LaserRays& scan, double range, double radius, int* invalid_rays);

/// Distances to obstacles per sector as fractions of `range` metres, for a disc of `radius` metres (0: a point)
/// at `from` on what `map` knows, the sectors in the frame of a robot heading `heading` radians in the map frame:
/// how far the disc moves along each sector's centre direction, in steps of an eighth of a cell, before it
/// overlaps a cell that is not passable (an obstacle, or off the map; a point: before it enters one). A disc that
/// already overlaps one gets a step's travel in every direction (a robot there has collided).
std::vector<double> sectorObstaclesInMap(const GridMap& map, MapPoint from, double heading, double range,
                                         double radius);

}  // namespace planners
}  // namespace ppp
