#include "ppp_core/segment_walk.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace {

using Cells = std::vector<Cell>;

std::pair<int, int> key(Cell c) { return {c.x, c.y}; }

Cell floorCell(double x, double y) { return Cell{static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y))}; }

/// True when the segment comes within `margin` of the cell's closed square (Liang-Barsky clipping).
bool touches(double x0, double y0, double x1, double y1, Cell cell, double margin) {
  double t_low = 0.0;
  double t_high = 1.0;
  const auto clip = [&](double start, double delta, double low, double high) {
    if (delta == 0.0) return start >= low && start <= high;
    double enter = (low - start) / delta;
    double leave = (high - start) / delta;
    if (enter > leave) std::swap(enter, leave);
    t_low = std::max(t_low, enter);
    t_high = std::min(t_high, leave);
    return t_low <= t_high;
  };
  return clip(x0, x1 - x0, cell.x - margin, cell.x + 1 + margin) &&
         clip(y0, y1 - y0, cell.y - margin, cell.y + 1 + margin);
}

/// Checks every property of a walk that does not depend on how corners are broken; returns the walk.
Cells checkedWalk(double x0, double y0, double x1, double y1) {
  const Cells walk = walkSegment(x0, y0, x1, y1);
  const std::string where = "segment (" + std::to_string(x0) + ", " + std::to_string(y0) + ") -> (" +
                            std::to_string(x1) + ", " + std::to_string(y1) + ")";
  EXPECT_EQ(walk.front(), floorCell(x0, y0)) << where;
  EXPECT_EQ(walk.back(), floorCell(x1, y1)) << where;
  std::set<std::pair<int, int>> seen;
  for (std::size_t i = 0; i < walk.size(); ++i) {
    EXPECT_TRUE(seen.insert(key(walk[i])).second) << where << ": cell repeated at " << i;
    EXPECT_TRUE(touches(x0, y0, x1, y1, walk[i], 1e-9)) << where << ": cell " << i << " not touched";
    if (i > 0) {
      EXPECT_EQ(std::abs(walk[i].x - walk[i - 1].x) + std::abs(walk[i].y - walk[i - 1].y), 1)
          << where << ": step " << i << " is not to an edge neighbour";
    }
  }
  // Dense samples: 1024 is a power of two, so on half-cell endpoints every sample is computed exactly. A
  // sample exactly on a grid corner is skipped: its cell (by floor) may be the one the x-first rule passes by.
  constexpr int kSamples = 1024;
  for (int k = 0; k <= kSamples; ++k) {
    const double t = static_cast<double>(k) / kSamples;
    const double x = x0 + t * (x1 - x0);
    const double y = y0 + t * (y1 - y0);
    if (x == std::floor(x) && y == std::floor(y)) continue;
    EXPECT_EQ(seen.count(key(floorCell(x, y))), 1u) << where << ": sample " << k << " outside the walk";
  }
  return walk;
}

TEST(SegmentWalkTest, HorizontalAndVertical) {
  EXPECT_EQ(walkSegment(0.5, 2.5, 3.5, 2.5), (Cells{{0, 2}, {1, 2}, {2, 2}, {3, 2}}));
  EXPECT_EQ(walkSegment(3.5, 2.5, 0.5, 2.5), (Cells{{3, 2}, {2, 2}, {1, 2}, {0, 2}}));
  EXPECT_EQ(walkSegment(1.5, 3.5, 1.5, 0.5), (Cells{{1, 3}, {1, 2}, {1, 1}, {1, 0}}));
  EXPECT_EQ(walkSegment(1.5, 0.2, 1.5, 1.9), (Cells{{1, 0}, {1, 1}}));
}

TEST(SegmentWalkTest, ExactDiagonalsTakeTheXStepFirstInEveryDirection) {
  EXPECT_EQ(walkSegment(0.5, 0.5, 2.5, 2.5), (Cells{{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}}));
  EXPECT_EQ(walkSegment(2.5, 2.5, 0.5, 0.5), (Cells{{2, 2}, {1, 2}, {1, 1}, {0, 1}, {0, 0}}));
  EXPECT_EQ(walkSegment(0.5, 2.5, 2.5, 0.5), (Cells{{0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}}));
  EXPECT_EQ(walkSegment(2.5, 0.5, 0.5, 2.5), (Cells{{2, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 2}}));
}

TEST(SegmentWalkTest, ShallowSlopes) {
  // y = 1 is crossed at x = 4.1375.
  EXPECT_EQ(walkSegment(0.2, 0.3, 4.7, 1.1), (Cells{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {4, 1}}));
  // Slope 1/3 from a centre crosses y = 1 exactly at the corner (2, 1).
  EXPECT_EQ(walkSegment(0.5, 0.5, 3.5, 1.5), (Cells{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {3, 1}}));
}

TEST(SegmentWalkTest, PassesBesideACornerOnTheCorrectSide) {
  const double tiny = std::ldexp(1.0, -50);
  EXPECT_EQ(walkSegment(0.5, 0.5 + tiny, 1.5, 1.5), (Cells{{0, 0}, {0, 1}, {1, 1}}));
  EXPECT_EQ(walkSegment(0.5, 0.5 - tiny, 1.5, 1.5), (Cells{{0, 0}, {1, 0}, {1, 1}}));
  EXPECT_EQ(walkSegment(0.5 - tiny, 0.5, 1.5, 1.5), (Cells{{0, 0}, {0, 1}, {1, 1}}));
}

TEST(SegmentWalkTest, PointsOnBoundariesBelongToTheLargerIndex) {
  EXPECT_EQ(walkSegment(1.2, 3.7, 1.2, 3.7), (Cells{{1, 3}}));
  EXPECT_EQ(walkSegment(2.0, 1.0, 2.0, 1.0), (Cells{{2, 1}}));
  EXPECT_EQ(walkSegment(0.5, 1.0, 2.5, 1.0), (Cells{{0, 1}, {1, 1}, {2, 1}}));
  EXPECT_EQ(walkSegment(2.0, 0.5, 0.5, 0.5), (Cells{{2, 0}, {1, 0}, {0, 0}}));
  EXPECT_EQ(walkSegment(0.5, 0.5, 1.0, 1.0), (Cells{{0, 0}, {1, 0}, {1, 1}}));
  EXPECT_EQ(walkSegment(-0.5, -0.5, 0.5, -0.5), (Cells{{-1, -1}, {0, -1}}));
}

TEST(SegmentWalkTest, MapSegmentsGoThroughTheMapFrame) {
  // A 3x2 map at 0.5 m per cell: map point (0.25, 0.75) is the top-left cell, (1.25, 0.25) the bottom-right.
  const MapFrame frame{3, 2, 0.5};
  EXPECT_EQ(walkMapSegment(frame, 0.25, 0.75, 1.25, 0.25), (Cells{{0, 0}, {1, 0}, {1, 1}, {2, 1}}));
  for (const Cell cell : walkMapSegment(frame, 0.25, 0.25, 1.25, 0.75)) {
    EXPECT_EQ(walkMapSegment(frame, frame.centreX(cell), frame.centreY(cell), frame.centreX(cell), frame.centreY(cell)),
              Cells{cell});
  }
}

TEST(SegmentWalkTest, RefusesCoordinatesItCannotWalk) {
  EXPECT_THROW(walkSegment(std::numeric_limits<double>::quiet_NaN(), 0, 1, 1), InvalidArgument);
  EXPECT_THROW(walkSegment(0, 0, 1, std::numeric_limits<double>::infinity()), InvalidArgument);
  EXPECT_THROW(walkSegment(0, 0, 1e12, 1), InvalidArgument);
}

TEST(SegmentWalkTest, RandomSegmentsCoverExactlyTheCellsTheyTouch) {
  Rng rng(20240);
  const auto coordinate = [&rng] { return rng.uniform01() * 14.0 - 2.0; };
  for (int trial = 0; trial < 3000; ++trial) {
    checkedWalk(coordinate(), coordinate(), coordinate(), coordinate());
  }
}

TEST(SegmentWalkTest, RandomHalfCellSegmentsBreakEveryExactCornerXFirst) {
  // Endpoints on multiples of 0.5 (centres, edges and corners): many segments pass exactly through corners.
  Rng rng(7);
  int corners_passed = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::int64_t half[4];  // x0, y0, x1, y1 in half cells
    for (std::int64_t& h : half) h = rng.uniformInt(0, 16);
    const Cells walk = checkedWalk(half[0] / 2.0, half[1] / 2.0, half[2] / 2.0, half[3] / 2.0);
    for (std::size_t i = 1; i + 1 < walk.size(); ++i) {
      const Cell before = walk[i - 1];
      const Cell after = walk[i + 1];
      if (before.x == after.x || before.y == after.y) continue;
      // The corner shared by the diagonal pair, in half cells; is it exactly on the segment's line?
      const std::int64_t corner_x = 2 * std::max(before.x, after.x);
      const std::int64_t corner_y = 2 * std::max(before.y, after.y);
      const std::int64_t cross =
          (half[2] - half[0]) * (corner_y - half[1]) - (half[3] - half[1]) * (corner_x - half[0]);
      if (cross != 0) continue;
      ++corners_passed;
      EXPECT_EQ(walk[i].y, before.y) << "trial " << trial << ": y step first at a corner";
    }
  }
  EXPECT_GT(corners_passed, 100);
}

}  // namespace
}  // namespace ppp
