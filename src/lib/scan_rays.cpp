#include "ppp_core/scan_rays.hpp"

#include <cmath>
#include <limits>

#include "ppp_core/sensor.hpp"

namespace ppp {

std::vector<float> windowRanges(const std::int8_t* cells, int range, int rays) {
  constexpr double kStep = 0.05;
  const int side = 2 * range + 1;
  const double limit = range + 0.5;
  std::vector<float> ranges(static_cast<std::size_t>(rays), std::numeric_limits<float>::infinity());
  for (int i = 0; i < rays; ++i) {
    const double angle = 2.0 * M_PI * i / rays;
    const double east = std::cos(angle);
    const double north = std::sin(angle);
    for (double t = kStep; t < 2.0 * limit; t += kStep) {
      const double x = east * t;
      const double y = -north * t;  // grid rows grow southwards
      if (std::fabs(x) >= limit || std::fabs(y) >= limit) break;
      const int dx = static_cast<int>(std::lround(x));
      const int dy = static_cast<int>(std::lround(y));
      const std::int8_t value = cells[(dy + range) * side + (dx + range)];
      if (value == kScanObstacle || value == kScanOutOfBounds) {
        ranges[i] = static_cast<float>(t);
        break;
      }
      if (value == kScanUnknown) break;
    }
  }
  return ranges;
}

}  // namespace ppp
