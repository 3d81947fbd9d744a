#include "ppp_core/picture.hpp"

#include <png.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>

#include "ppp_core/canvas.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/text_file.hpp"

namespace ppp {

namespace {

void checkPictureSize(const Problem& problem, const PictureOptions& options) {
  const long long width = static_cast<long long>(problem.width) * options.cell_pixels + (options.grid_lines ? 1 : 0);
  const long long height = static_cast<long long>(problem.height) * options.cell_pixels + (options.grid_lines ? 1 : 0);
  if (width > kMaxPictureSide || height > kMaxPictureSide) {
    throw InvalidArgument("cell_pixels", "a " + std::to_string(problem.width) + "x" + std::to_string(problem.height) +
                                             " grid at " + std::to_string(options.cell_pixels) +
                                             " pixels per cell makes a " + std::to_string(width) + "x" +
                                             std::to_string(height) + " picture; the limit is " +
                                             std::to_string(kMaxPictureSide) + " pixels per side");
  }
}

/// @throws InvalidArgument naming `what` when a cell of `cells` is off the problem's grid.
void checkOnGrid(const Problem& problem, const std::vector<Cell>& cells, const char* what) {
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Cell c = cells[i];
    if (c.x < 0 || c.y < 0 || c.x >= problem.width || c.y >= problem.height) {
      throw InvalidArgument(what, "step " + std::to_string(i) + " (" + std::to_string(c.x) + ", " +
                                      std::to_string(c.y) + ") is outside the " + std::to_string(problem.width) +
                                      "x" + std::to_string(problem.height) + " grid");
    }
  }
}

}  // namespace

void PictureOptions::validate() const {
  if (cell_pixels < 1 || cell_pixels > 256) {
    throw InvalidArgument("cell_pixels", "expected an integer in [1, 256], got " + std::to_string(cell_pixels));
  }
  if (grid_lines && cell_pixels < 3) {
    throw InvalidArgument("cell_pixels", "grid lines need at least 3 pixels per cell, got " +
                                             std::to_string(cell_pixels) + "; use more or turn grid_lines off");
  }
}

int pictureWidth(int width, const PictureOptions& options) {
  return width * options.cell_pixels + (options.grid_lines ? 1 : 0);
}

int pictureHeight(int height, const PictureOptions& options) {
  return height * options.cell_pixels + (options.grid_lines ? 1 : 0);
}

Pixel cellOrigin(Cell c, const PictureOptions& options) {
  return Pixel{c.x * options.cell_pixels, c.y * options.cell_pixels};
}

Pixel cellCentre(Cell c, const PictureOptions& options) {
  const Pixel o = cellOrigin(c, options);
  return Pixel{o.x + options.cell_pixels / 2, o.y + options.cell_pixels / 2};
}

std::vector<std::uint8_t> renderProblemRgb(const Problem& problem, const std::vector<Cell>& path,
                                           const PictureOptions& options, const std::vector<Cell>& marked) {
  options.validate();
  validateProblem(problem);
  checkPictureSize(problem, options);
  checkOnGrid(problem, path, "path");
  checkOnGrid(problem, marked, "marked");
  const Grid grid = decodeGrid(problem);
  Canvas<Rgb> canvas(pictureWidth(problem.width, options), pictureHeight(problem.height, options),
                     options.grid_lines ? kGridLineColour : kFreeColour);
  for (int y = 0; y < problem.height; ++y) {
    for (int x = 0; x < problem.width; ++x) {
      const Cell c{x, y};
      canvas.fillCell(c, grid.isObstacle(c) ? kObstacleColour : kFreeColour, options);
    }
  }
  for (const Cell c : marked) canvas.fillCell(c, kMarkedColour, options);
  const int thickness = std::max(1, options.cell_pixels / 8);
  for (std::size_t i = 1; i < path.size(); ++i) {
    canvas.line(cellCentre(path[i - 1], options), cellCentre(path[i], options), thickness, kPathColour);
  }
  for (const Cell c : path) canvas.disc(cellCentre(c, options), options.cell_pixels / 5, kPathColour);
  // Start and goal go last so they stay solid squares where the path enters them.
  canvas.fillCell(problem.start, kStartColour, options);
  canvas.fillCell(problem.goal, kGoalColour, options);
  std::vector<std::uint8_t> rgb;
  rgb.reserve(canvas.pixels().size() * 3);
  for (const Rgb& p : canvas.pixels()) rgb.insert(rgb.end(), {p.r, p.g, p.b});
  return rgb;
}

std::string encodePng(const std::vector<std::uint8_t>& rgb, int width, int height) {
  if (width < 1 || height < 1 || width > kMaxPictureSide || height > kMaxPictureSide) {
    throw InvalidArgument("png size", "expected width and height in [1, " + std::to_string(kMaxPictureSide) +
                                          "], got " + std::to_string(width) + "x" + std::to_string(height));
  }
  const std::size_t expected = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3;
  if (rgb.size() != expected) {
    throw InvalidArgument("png pixels", "expected " + std::to_string(expected) + " bytes for " + std::to_string(width) +
                                            "x" + std::to_string(height) + " RGB, got " + std::to_string(rgb.size()));
  }
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(width);
  image.height = static_cast<png_uint_32>(height);
  image.format = PNG_FORMAT_RGB;
  std::string png(PNG_IMAGE_PNG_SIZE_MAX(image), '\0');
  png_alloc_size_t size = png.size();
  // The simplified API keeps libpng's setjmp/longjmp error handling away from C++ objects.
  if (!png_image_write_to_memory(&image, png.data(), &size, 0, rgb.data(), 0, nullptr)) {
    const std::string message = image.message;
    png_image_free(&image);
    throw Error("PNG encoding failed: " + message);
  }
  png_image_free(&image);
  png.resize(size);
  png.shrink_to_fit();  // the worst-case buffer is many times the compressed size: callers may keep many PNGs
  return png;
}

void writeProblemPng(const Problem& problem, const std::vector<Cell>& path, const std::string& png_path,
                     const PictureOptions& options, const std::vector<Cell>& marked) {
  const std::vector<std::uint8_t> rgb = renderProblemRgb(problem, path, options, marked);
  writeFileAtomically(png_path,
                      encodePng(rgb, pictureWidth(problem.width, options), pictureHeight(problem.height, options)));
}

}  // namespace ppp
