#include "ppp_core/picture.hpp"

#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"

namespace ppp {
namespace {

namespace fs = std::filesystem;

/// 4x3, a vbar down column 1 from the top, start top-left, goal bottom-right:
///   S#..
///   .#..
///   ...G
Problem tinyProblem() {
  Problem p = Problem::empty(4, 3, 2);
  p.obstacles = {{Shape::VerticalBar, 1, 0, 2, 1}};
  return p;
}

const std::vector<Cell> kTinyPath = {{0, 0}, {0, 1}, {0, 2}, {1, 2}, {2, 2}, {3, 2}};

Rgb pixelAt(const std::vector<std::uint8_t>& rgb, int width, Pixel p) {
  const std::size_t i = (static_cast<std::size_t>(p.y) * width + p.x) * 3;
  return Rgb{rgb[i], rgb[i + 1], rgb[i + 2]};
}

std::string text(Rgb c) {
  return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ")";
}

TEST(PictureTest, RendersCellsPathAndGridLines) {
  const PictureOptions options;  // 16 pixels per cell, grid lines
  const Problem p = tinyProblem();
  const int width = pictureWidth(p.width, options);
  const int height = pictureHeight(p.height, options);
  EXPECT_EQ(width, 65);
  EXPECT_EQ(height, 49);
  const std::vector<std::uint8_t> rgb = renderProblemRgb(p, kTinyPath, options);
  ASSERT_EQ(rgb.size(), static_cast<std::size_t>(width * height * 3));
  auto at = [&](Pixel px) { return text(pixelAt(rgb, width, px)); };

  EXPECT_EQ(at(cellCentre({0, 0}, options)), text(kStartColour));
  EXPECT_EQ(at(cellCentre({3, 2}, options)), text(kGoalColour));
  EXPECT_EQ(at(cellCentre({1, 0}, options)), text(kObstacleColour));
  EXPECT_EQ(at(cellCentre({1, 1}, options)), text(kObstacleColour));
  EXPECT_EQ(at(cellCentre({2, 0}, options)), text(kFreeColour));
  EXPECT_EQ(at(cellCentre({3, 1}, options)), text(kFreeColour));
  // Path dots at the centres of the cells it passes, and the line between them.
  EXPECT_EQ(at(cellCentre({0, 1}, options)), text(kPathColour));
  EXPECT_EQ(at(cellCentre({2, 2}, options)), text(kPathColour));
  EXPECT_EQ(at(Pixel{8, 30}), text(kPathColour));   // between (0, 1) and (0, 2), across the grid line at y = 32
  EXPECT_EQ(at(Pixel{32, 40}), text(kPathColour));  // between (1, 2) and (2, 2), on the grid line at x = 32
  // The path does not wander into cells it does not visit.
  EXPECT_EQ(at(Pixel{20, 40 - 5}), text(kFreeColour));
  // Grid lines on cell borders and the picture edge; the start stays a solid square where the path enters.
  EXPECT_EQ(at(Pixel{0, 0}), text(kGridLineColour));
  EXPECT_EQ(at(Pixel{16, 4}), text(kGridLineColour));
  EXPECT_EQ(at(Pixel{64, 48}), text(kGridLineColour));
  EXPECT_EQ(at(Pixel{8, 15}), text(kStartColour));
  EXPECT_EQ(at(Pixel{1, 1}), text(kStartColour));
}

TEST(PictureTest, WithoutGridLinesCellsTileThePicture) {
  PictureOptions options;
  options.cell_pixels = 5;
  options.grid_lines = false;
  const Problem p = tinyProblem();
  EXPECT_EQ(pictureWidth(p.width, options), 20);
  EXPECT_EQ(pictureHeight(p.height, options), 15);
  const std::vector<std::uint8_t> rgb = renderProblemRgb(p, {}, options);
  ASSERT_EQ(rgb.size(), 20u * 15u * 3u);
  EXPECT_EQ(text(pixelAt(rgb, 20, Pixel{0, 0})), text(kStartColour));
  EXPECT_EQ(text(pixelAt(rgb, 20, Pixel{5, 0})), text(kObstacleColour));
  EXPECT_EQ(text(pixelAt(rgb, 20, Pixel{9, 9})), text(kObstacleColour));
  EXPECT_EQ(text(pixelAt(rgb, 20, Pixel{5, 10})), text(kFreeColour));
  EXPECT_EQ(text(pixelAt(rgb, 20, Pixel{19, 14})), text(kGoalColour));
}

TEST(PictureTest, MarkedCellsArePinkUnderThePath) {
  PictureOptions options;
  options.cell_pixels = 5;
  options.grid_lines = false;
  // Cells (2, 0) and (0, 1) marked; (0, 1) is on the path, whose dot covers its centre.
  const std::vector<std::uint8_t> rgb = renderProblemRgb(tinyProblem(), kTinyPath, options, {{2, 0}, {0, 1}});
  EXPECT_EQ(text(pixelAt(rgb, 20, Pixel{12, 2})), text(kMarkedColour));   // the centre of (2, 0)
  EXPECT_EQ(text(pixelAt(rgb, 20, Pixel{0, 5})), text(kMarkedColour));    // a corner of (0, 1)
  EXPECT_EQ(text(pixelAt(rgb, 20, Pixel{2, 7})), text(kPathColour));      // its centre: the path's dot
  EXPECT_EQ(text(pixelAt(rgb, 20, Pixel{17, 2})), text(kFreeColour));     // (3, 0) is not marked
  EXPECT_THROW(renderProblemRgb(tinyProblem(), {}, options, {{0, 3}}), InvalidArgument);
}

TEST(PictureTest, PngFileReadsBackWithLibpng) {
  const Problem p = tinyProblem();
  const PictureOptions options;
  const fs::path path = fs::temp_directory_path() / ("ppp_picture_test_" + std::to_string(::getpid()) + ".png");
  writeProblemPng(p, kTinyPath, path.string(), options);

  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_file(&image, path.string().c_str())) << image.message;
  EXPECT_EQ(image.width, 65u);
  EXPECT_EQ(image.height, 49u);
  image.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(image));
  ASSERT_TRUE(png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr)) << image.message;
  EXPECT_EQ(text(pixelAt(pixels, 65, cellCentre({0, 0}, options))), text(kStartColour));
  EXPECT_EQ(text(pixelAt(pixels, 65, cellCentre({1, 1}, options))), text(kObstacleColour));
  EXPECT_EQ(pixels, renderProblemRgb(p, kTinyPath, options));
  fs::remove(path);
}

TEST(PictureTest, EncodePngGivesPngBytes) {
  const std::vector<std::uint8_t> rgb(3 * 2 * 3, 128);
  const std::string png = encodePng(rgb, 3, 2);
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_THROW(encodePng(rgb, 3, 3), InvalidArgument);
  EXPECT_THROW(encodePng(rgb, 0, 2), InvalidArgument);
}

TEST(PictureTest, BadInputIsRefused) {
  const Problem p = tinyProblem();
  PictureOptions options;
  options.cell_pixels = 0;
  EXPECT_THROW(renderProblemRgb(p, {}, options), InvalidArgument);
  options.cell_pixels = 2;
  EXPECT_THROW(renderProblemRgb(p, {}, options), InvalidArgument);  // too small for grid lines
  options.grid_lines = false;
  EXPECT_NO_THROW(renderProblemRgb(p, {}, options));
  EXPECT_THROW(renderProblemRgb(p, {{0, 0}, {4, 0}}, {}), InvalidArgument);
  EXPECT_THROW(renderProblemRgb(Problem::empty(4096, 4096, 0), {}, {}), InvalidArgument);
  try {
    writeProblemPng(p, {}, "/nonexistent/dir/picture.png", {});
    ADD_FAILURE() << "wrote into a missing directory";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/picture.png"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ppp
