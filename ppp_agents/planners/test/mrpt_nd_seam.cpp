// CHolonomicND asked for a target half its range away, nothing within range, in each of its 72 sector directions.
// With the way open it should head for the target (VFF and FullEval do, in all 72); for the five sectors within
// two of the seam at -pi/+pi it does not.
#include <mrpt/math/TPoint2D.h>
#include <mrpt/nav/holonomic/CHolonomicND.h>
#include <mrpt/nav/holonomic/ClearanceDiagram.h>

#include <cmath>
#include <cstdio>

int main() {
  const int sectors = 72;
  int straight = 0;
  for (int k = 0; k < sectors; ++k) {
    const double target = -M_PI + (k + 0.5) * 2 * M_PI / sectors;  // the centre of sector k
    mrpt::nav::CHolonomicND nd;
    mrpt::nav::ClearanceDiagram clearance;
    mrpt::nav::CAbstractHolonomicReactiveMethod::NavInput in;
    in.obstacles.assign(sectors, 1.0);  // nothing within range
    in.targets = {mrpt::math::TPoint2D(0.5 * std::cos(target), 0.5 * std::sin(target))};
    in.maxRobotSpeed = 1.0;
    in.maxObstacleDist = 1.0;
    in.clearance = &clearance;
    mrpt::nav::CAbstractHolonomicReactiveMethod::NavOutput out;
    nd.navigate(in, out);
    const double off = std::remainder(out.desiredDirection - target, 2 * M_PI) * 180 / M_PI;
    if (std::abs(off) < 1e-6) {
      ++straight;
    } else {
      std::printf("target in sector %d (%.1f deg): ND heads %.1f deg, %.1f deg off\n", k, target * 180 / M_PI,
                  out.desiredDirection * 180 / M_PI, off);
    }
  }
  std::printf("ND heads straight for %d of %d targets\n", straight, sectors);
  return 0;
}
