#include "ppp_core/laser.hpp"

#include <cmath>

namespace ppp {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

LaserBeams LaserBeams::of(const MotionOptions& options) {
  LaserBeams beams;
  beams.count = options.laser_beams;
  beams.range_max = options.laser_range;
  beams.noise = options.laser_noise;
  if (options.laser_field_of_view >= 360) {
    beams.angle_min = -kPi;
    beams.angle_increment = 2 * kPi / beams.count;
  } else {
    const double field = options.laser_field_of_view * kPi / 180;
    beams.angle_min = beams.count > 1 ? -field / 2 : 0;
    beams.angle_increment = beams.count > 1 ? field / (beams.count - 1) : 0;
  }
  for (int i = 0; i < beams.count; ++i) {
    beams.cosines.push_back(std::cos(beams.angle_min + i * beams.angle_increment));
    beams.sines.push_back(std::sin(beams.angle_min + i * beams.angle_increment));
  }
  return beams;
}

double standardNormal(Rng* rng) {
  const double u = 1 - rng->uniform01();  // in (0, 1]: the logarithm is finite
  const double v = rng->uniform01();
  return std::sqrt(-2 * std::log(u)) * std::cos(2 * kPi * v);
}

void scanLaser(const SquareWorld& world, const Pose2D& pose, const LaserBeams& beams, Rng* noise,
               std::vector<float>* ranges) {
  ranges->resize(beams.count);
  // The beams' directions turned by the heading: no trigonometry per beam.
  world.castFan(pose.x, pose.y, std::cos(pose.theta), std::sin(pose.theta), beams.cosines, beams.sines,
                beams.range_max, ranges->data());
  if (beams.noise <= 0) return;
  for (float& range : *ranges) {
    if (std::isfinite(range)) range = static_cast<float>(std::max(0.0, range + beams.noise * standardNormal(noise)));
  }
}

}  // namespace ppp
