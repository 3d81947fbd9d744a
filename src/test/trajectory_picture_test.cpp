// A continuous run drawn over its problem: the trajectory's pixels, the robot's outline and heading.

#include "ppp_core/trajectory_picture.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "ppp_core/error.hpp"

namespace ppp {
namespace {

Rgb pixelAt(const std::vector<std::uint8_t>& rgb, int width, int x, int y) {
  const std::size_t i = 3 * (static_cast<std::size_t>(y) * width + x);
  return Rgb{rgb[i], rgb[i + 1], rgb[i + 2]};
}

TEST(TrajectoryPictureTest, TheTrajectoryIsACurveThroughTheRobotsCentres) {
  // 4x3 cells of 16 pixels without grid lines; metres are cells (resolution 1). The robot drives along the middle
  // row's centre line (y = 1.5 m, pixel row 24) from x = 0.5 m to x = 2.5 m and stops heading north.
  const Problem problem = Problem::empty(4, 3, 0);
  PictureOptions options;
  options.grid_lines = false;
  const std::vector<Pose2D> poses = {{0.5, 1.5, 0}, {1.5, 1.5, 0}, {2.5, 1.5, 1.5707963267948966}};
  const std::vector<std::uint8_t> rgb = renderTrajectoryRgb(problem, poses, 1.0, 0.3, options);
  ASSERT_EQ(rgb.size(), renderProblemRgb(problem, {}, options).size());
  EXPECT_EQ(pixelAt(rgb, 64, 20, 24), kPathColour);  // x = 1.25 m on the line
  EXPECT_EQ(pixelAt(rgb, 64, 20, 18), kFreeColour);  // 6 pixels above it
  // The heading line points up the picture (north) from the last pose at pixel (40, 24).
  EXPECT_NE(pixelAt(rgb, 64, 40, 21), kPathColour);
  EXPECT_NE(pixelAt(rgb, 64, 40, 21), kFreeColour);
  EXPECT_EQ(pixelAt(rgb, 64, 44, 20), kFreeColour);  // inside the disc, beside the heading line
}

TEST(TrajectoryPictureTest, NoPoseIsRefused) {
  EXPECT_THROW(renderTrajectoryRgb(Problem::empty(4, 3, 0), {}, 1.0, 0.3), InvalidArgument);
}

}  // namespace
}  // namespace ppp
