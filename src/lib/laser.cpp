#include "ppp_core/laser.hpp"

#include <cmath>

namespace ppp {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

LaserBeams LaserBeams::of(const MotionOptions& options) {
  const int count = options.laser_beams;
  if (options.laser_field_of_view >= 360) {
    return fan(count, -kPi, 2 * kPi / count, options.laser_range, options.laser_noise);
  }
  const double field = options.laser_field_of_view * kPi / 180;
  return fan(count, count > 1 ? -field / 2 : 0, count > 1 ? field / (count - 1) : 0, options.laser_range,
             options.laser_noise);
}

LaserBeams LaserBeams::fan(int count, double angle_min, double angle_increment, double range_max, double noise) {
  LaserBeams beams;
  beams.count = count;
  beams.angle_min = angle_min;
  beams.angle_increment = angle_increment;
  beams.range_max = range_max;
  beams.noise = noise;
  for (int i = 0; i < count; ++i) {
    beams.cosines.push_back(std::cos(angle_min + i * angle_increment));
    beams.sines.push_back(std::sin(angle_min + i * angle_increment));
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
