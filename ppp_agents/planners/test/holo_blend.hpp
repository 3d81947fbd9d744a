#pragma once
// MRPT's own obstacle distances for a round holonomic robot (CPTG_Holo_Blend, what its reactive navigator gives a
// holonomic method), to check sectorObstaclesForDisc against and to time it beside.
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/nav/tpspace/CPTG_Holo_Blend.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "sector_obstacles.hpp"

namespace ppp {
namespace planners {
namespace test {

/// MRPT's straight trajectories for a round holonomic robot of `radius` metres at rest, 72 of them as the
/// holonomic methods' sectors, `range` metres long.
inline mrpt::nav::CPTG_Holo_Blend holoBlend(double radius, double range) {
  mrpt::config::CConfigFileMemory config;
  const std::string s = "ptg";
  config.write(s, "num_paths", kReactiveSectors);
  config.write(s, "refDistance", range);
  config.write(s, "T_ramp_max", 0.9);
  config.write(s, "v_max_mps", 0.5);
  config.write(s, "w_max_dps", 90.0);
  config.write(s, "robot_radius", radius);
  mrpt::nav::CPTG_Holo_Blend ptg(config, s);
  ptg.initialize();
  return ptg;
}

/// The fractions of `range` MRPT's trajectories travel before the disc touches a return of `scan`.
inline std::vector<double> holoBlendObstacles(const mrpt::nav::CPTG_Holo_Blend& ptg, const LaserRays& scan, double range) {
  std::vector<double> tp_obstacles;
  ptg.initTPObstacles(tp_obstacles);
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    if (!std::isfinite(scan.ranges[i])) continue;
    const double angle = scan.angle_min + i * scan.angle_increment;
    ptg.updateTPObstacle(scan.ranges[i] * std::cos(angle), scan.ranges[i] * std::sin(angle), tp_obstacles);
  }
  for (double& d : tp_obstacles) d = std::clamp(d / range, 0.0, 1.0);
  return tp_obstacles;
}

}  // namespace test
}  // namespace planners
}  // namespace ppp
