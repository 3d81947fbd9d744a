#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ppp_core/grid.hpp"
#include "ppp_core/problem.hpp"

namespace ppp {

/// An 8-bit RGB colour.
struct Rgb {
  std::uint8_t r = 0;  ///< Red.
  std::uint8_t g = 0;  ///< Green.
  std::uint8_t b = 0;  ///< Blue.
  /// Colours are equal when all channels are.
  friend bool operator==(const Rgb& a, const Rgb& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }
  /// Negation of ==.
  friend bool operator!=(const Rgb& a, const Rgb& b) { return !(a == b); }
};

/// Colour of free cells.
constexpr Rgb kFreeColour{255, 255, 255};
/// Colour of obstacle cells.
constexpr Rgb kObstacleColour{64, 64, 64};
/// Colour of the start cell.
constexpr Rgb kStartColour{40, 170, 60};
/// Colour of the goal cell.
constexpr Rgb kGoalColour{210, 40, 40};
/// Colour of the path line and its dots.
constexpr Rgb kPathColour{30, 80, 230};
/// Colour of marked cells (a loop's cycle).
constexpr Rgb kMarkedColour{245, 190, 235};
/// Colour of the grid lines between cells.
constexpr Rgb kGridLineColour{200, 200, 200};

/// A pixel position in a picture: x to the right, y down, (0, 0) at the top-left.
struct Pixel {
  int x = 0;  ///< Column.
  int y = 0;  ///< Row.
};

/// Largest picture side, in pixels, that renderProblemRgb() accepts.
constexpr int kMaxPictureSide = 8192;

/// How a problem is drawn.
struct PictureOptions {
  int cell_pixels = 16;    ///< Side of one cell in pixels, in [1, 256] (at least 3 with grid lines).
  bool grid_lines = true;  ///< Draw 1-pixel lines around every cell (adds one pixel to each picture side).

  /// Checks the options. @throws InvalidArgument naming the option.
  void validate() const;
};

/// Width in pixels of the picture of a `width`-cell grid: width * cell_pixels (+1 with grid lines).
int pictureWidth(int width, const PictureOptions& options);
/// Height in pixels of the picture of a `height`-cell grid: height * cell_pixels (+1 with grid lines).
int pictureHeight(int height, const PictureOptions& options);

/// Top-left pixel of a cell's square; with grid lines the square's first row and column are the line.
Pixel cellOrigin(Cell c, const PictureOptions& options);
/// Centre pixel of a cell.
Pixel cellCentre(Cell c, const PictureOptions& options);

/// Draws a problem as row-major RGB bytes (3 per pixel, pictureWidth × pictureHeight, row 0 at the top,
/// like the grid): free cells white, obstacles dark grey, start green, goal red, and the optional `path`
/// (cells in order; may be empty) as a blue line through the cell centres with a dot on each cell, over the
/// `marked` cells filled pink (a loop's cycle).
/// @throws InvalidArgument for an invalid problem or options, a path or marked cell off the grid, or a picture
/// larger than kMaxPictureSide.
std::vector<std::uint8_t> renderProblemRgb(const Problem& problem, const std::vector<Cell>& path = {},
                                           const PictureOptions& options = {}, const std::vector<Cell>& marked = {});

/// Encodes row-major 8-bit RGB pixels as PNG file bytes, in memory (for files and base64 thumbnails).
/// @throws InvalidArgument when the buffer size disagrees with width × height, Error when libpng fails.
std::string encodePng(const std::vector<std::uint8_t>& rgb, int width, int height);

/// Renders a problem (see renderProblemRgb) and writes it as a PNG file, atomically.
/// @throws InvalidArgument as renderProblemRgb, IoError naming `png_path` when it cannot be written.
void writeProblemPng(const Problem& problem, const std::vector<Cell>& path, const std::string& png_path,
                     const PictureOptions& options = {}, const std::vector<Cell>& marked = {});

}  // namespace ppp
