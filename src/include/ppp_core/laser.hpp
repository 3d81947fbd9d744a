#pragma once

#include <vector>

#include "ppp_core/kinematics.hpp"
#include "ppp_core/motion_options.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/square_world.hpp"

namespace ppp {

/// A 2D laser's beams, as sensor_msgs/LaserScan describes them: beam i points at angle_min + i x angle_increment
/// radians from the robot's heading.
struct LaserBeams {
  int count = 360;               ///< Beams per scan.
  double angle_min = 0;          ///< Radians from the heading of the first beam.
  double angle_increment = 0;    ///< Radians between beams.
  double range_max = 3.5;        ///< Metres; farther returns read +infinity.
  double noise = 0;              ///< Standard deviation of the Gaussian noise on each range, metres.
  /// Beam i's unit vector in the robot's frame: (cos, sin) of angle_min + i x angle_increment, made by of().
  std::vector<double> cosines, sines;
  /// The beams `options` give: a full circle from -pi with count beams 2 pi / count apart, else the field of
  /// view centred ahead with its two edges included.
  static LaserBeams of(const MotionOptions& options);
  /// `count` beams from `angle_min`, `angle_increment` apart (as a sensor_msgs/LaserScan describes them).
  static LaserBeams fan(int count, double angle_min, double angle_increment, double range_max, double noise);
};

/// The ranges a laser with `beams` (made by LaserBeams::of()) at `pose` reads in `world`, written into `ranges`
/// (resized): each cast exactly (SquareWorld::castFan), +infinity for no return; with noise, each finite range
/// plus a Gaussian draw from `noise` (never below 0).
void scanLaser(const SquareWorld& world, const Pose2D& pose, const LaserBeams& beams, Rng* noise,
               std::vector<float>* ranges);

/// A standard normal draw (Box-Muller, from two uniform draws of `rng`).
double standardNormal(Rng* rng);

}  // namespace ppp
