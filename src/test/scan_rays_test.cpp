// windowRanges: a scan window as laser ranges. Expected values by hand: rays are marched from the agent's
// cell centre in 1/20-cell steps, so a return from the cell boundary at distance d is reported in [d, d + 0.05].
#include "ppp_core/scan_rays.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ppp_core/sensor.hpp"

namespace ppp {
namespace {

constexpr int kRange = 2;
constexpr int kSide = 2 * kRange + 1;

/// A range-2 window, all free, with `value` at offset (dx, dy) from the agent (grid y down).
std::vector<std::int8_t> windowWith(int dx, int dy, std::int8_t value) {
  std::vector<std::int8_t> cells(kSide * kSide, kScanFree);
  cells[(dy + kRange) * kSide + (dx + kRange)] = value;
  return cells;
}

TEST(ScanRaysTest, AnOpenWindowGivesNoReturns) {
  const std::vector<std::int8_t> cells(kSide * kSide, kScanFree);
  for (float r : windowRanges(cells.data(), kRange, 72)) EXPECT_TRUE(std::isinf(r));
}

TEST(ScanRaysTest, ObstaclesAndTheEdgeReturnAtTheirBoundary) {
  // Four rays: east, north (grid row - 1), west, south.
  const auto east = windowRanges(windowWith(2, 0, kScanObstacle).data(), kRange, 4);
  EXPECT_NEAR(east[0], 1.5, 0.051);
  EXPECT_TRUE(std::isinf(east[1]) && std::isinf(east[2]) && std::isinf(east[3]));

  const auto north = windowRanges(windowWith(0, -1, kScanObstacle).data(), kRange, 4);
  EXPECT_NEAR(north[1], 0.5, 0.051);
  EXPECT_TRUE(std::isinf(north[0]) && std::isinf(north[2]) && std::isinf(north[3]));

  const auto south = windowRanges(windowWith(0, 2, kScanOutOfBounds).data(), kRange, 4);
  EXPECT_NEAR(south[3], 1.5, 0.051);
}

TEST(ScanRaysTest, AnUnknownCellEndsTheRayWithoutAReturn) {
  // West: unknown at distance 1 hides the obstacle behind it.
  std::vector<std::int8_t> cells = windowWith(-1, 0, kScanUnknown);
  cells[(0 + kRange) * kSide + (-2 + kRange)] = kScanObstacle;
  const auto ranges = windowRanges(cells.data(), kRange, 4);
  EXPECT_TRUE(std::isinf(ranges[2]));
}

}  // namespace
}  // namespace ppp
