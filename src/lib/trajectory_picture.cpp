#include "ppp_core/trajectory_picture.hpp"

#include <algorithm>
#include <cmath>

#include "ppp_core/canvas.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/text_file.hpp"

namespace ppp {

namespace {

constexpr Rgb kRobotColour{240, 120, 0};

}  // namespace

Pixel mapPixel(double x, double y, int rows, double resolution, const PictureOptions& options) {
  // Map frame (metres, y up) to pixels: a cell's square spans cell_pixels from its origin (past its grid line).
  const double scale = options.cell_pixels / resolution;
  const double inset = options.grid_lines ? 0.5 : 0;
  return Pixel{static_cast<int>(std::lround(x * scale + inset - 0.5)),
               static_cast<int>(std::lround((rows * resolution - y) * scale + inset - 0.5))};
}

std::vector<std::uint8_t> renderTrajectoryRgb(const Problem& problem, const std::vector<Pose2D>& poses,
                                              double resolution, double radius, const PictureOptions& options) {
  if (poses.empty()) throw InvalidArgument("poses", "expected at least one pose of the robot to draw");
  const std::vector<std::uint8_t> base = renderProblemRgb(problem, {}, options);
  const int width = pictureWidth(problem.width, options), height = pictureHeight(problem.height, options);
  Canvas<Rgb> canvas(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = 3 * (static_cast<std::size_t>(y) * width + x);
      canvas.set(x, y, Rgb{base[i], base[i + 1], base[i + 2]});
    }
  }
  const double scale = options.cell_pixels / resolution;
  const auto pixel = [&](double x, double y) { return mapPixel(x, y, problem.height, resolution, options); };
  const int thickness = std::max(1, options.cell_pixels / 8);
  for (std::size_t i = 1; i < poses.size(); ++i) {
    canvas.line(pixel(poses[i - 1].x, poses[i - 1].y), pixel(poses[i].x, poses[i].y), thickness, kPathColour);
  }
  const Pose2D& last = poses.back();
  const double drawn = std::max(radius, 3.0 / scale);
  constexpr int kOutlineSteps = 64;
  for (int k = 0; k < kOutlineSteps; ++k) {
    const double a = 2 * 3.14159265358979323846 * k / kOutlineSteps, b = a + 2 * 3.14159265358979323846 / kOutlineSteps;
    canvas.line(pixel(last.x + drawn * std::cos(a), last.y + drawn * std::sin(a)),
                pixel(last.x + drawn * std::cos(b), last.y + drawn * std::sin(b)), 1, kRobotColour);
  }
  canvas.line(pixel(last.x, last.y),
              pixel(last.x + drawn * std::cos(last.theta), last.y + drawn * std::sin(last.theta)), thickness,
              kRobotColour);
  std::vector<std::uint8_t> rgb;
  rgb.reserve(canvas.pixels().size() * 3);
  for (const Rgb& p : canvas.pixels()) rgb.insert(rgb.end(), {p.r, p.g, p.b});
  return rgb;
}

void writeTrajectoryPng(const Problem& problem, const std::vector<Pose2D>& poses, double resolution, double radius,
                        const std::string& png_path, const PictureOptions& options) {
  const std::vector<std::uint8_t> rgb = renderTrajectoryRgb(problem, poses, resolution, radius, options);
  writeFileAtomically(png_path,
                      encodePng(rgb, pictureWidth(problem.width, options), pictureHeight(problem.height, options)));
}

}  // namespace ppp
