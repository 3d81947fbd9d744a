#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <utility>
#include <vector>

#include "ppp_core/grid.hpp"
#include "ppp_core/picture.hpp"

namespace ppp {

/// A row-major picture of `Colour` pixels (RGB for PNG pictures, palette indices for GIF frames) that ignores
/// drawing outside its bounds.
template <typename Colour>
class Canvas {
 public:
  /// A `width` × `height` canvas filled with `background`.
  Canvas(int width, int height, Colour background = Colour{})
      : width_(width), height_(height), pixels_(static_cast<std::size_t>(width) * height, background) {}

  /// Sets one pixel.
  void set(int x, int y, Colour colour) {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
    pixels_[static_cast<std::size_t>(y) * width_ + x] = colour;
  }

  /// Fills the rectangle [x0, x1) × [y0, y1) (clipped to the canvas).
  void fill(int x0, int y0, int x1, int y1, Colour colour) {
    x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, width_), y1 = std::min(y1, height_);
    if (x0 >= x1) return;
    for (int y = y0; y < y1; ++y) {
      const auto row = pixels_.begin() + static_cast<std::ptrdiff_t>(y) * width_;
      std::fill(row + x0, row + x1, colour);
    }
  }

  /// A filled disc of `radius` pixels (0 is a single pixel).
  void disc(Pixel centre, int radius, Colour colour) {
    for (int dy = -radius; dy <= radius; ++dy) {
      for (int dx = -radius; dx <= radius; ++dx) {
        if (dx * dx + dy * dy <= radius * radius + radius) set(centre.x + dx, centre.y + dy, colour);
      }
    }
  }

  /// A Bresenham line from a to b, `thickness` pixels wide.
  void line(Pixel a, Pixel b, int thickness, Colour colour) {
    const int dx = std::abs(b.x - a.x);
    const int dy = -std::abs(b.y - a.y);
    const int sx = a.x < b.x ? 1 : -1;
    const int sy = a.y < b.y ? 1 : -1;
    int error = dx + dy;
    const int lo = -(thickness - 1) / 2;
    const int hi = thickness / 2;
    for (Pixel p = a;;) {
      fill(p.x + lo, p.y + lo, p.x + hi + 1, p.y + hi + 1, colour);
      if (p.x == b.x && p.y == b.y) break;
      const int twice = 2 * error;
      if (twice >= dy) {
        error += dy;
        p.x += sx;
      }
      if (twice <= dx) {
        error += dx;
        p.y += sy;
      }
    }
  }

  /// Colours a cell's square as drawn with `options`, leaving its grid lines alone.
  void fillCell(Cell c, Colour colour, const PictureOptions& options) {
    const Pixel o = cellOrigin(c, options);
    const int inset = options.grid_lines ? 1 : 0;
    fill(o.x + inset, o.y + inset, o.x + options.cell_pixels, o.y + options.cell_pixels, colour);
  }

  /// Columns.
  int width() const { return width_; }
  /// Rows.
  int height() const { return height_; }
  /// The pixels, row-major from the top-left.
  const std::vector<Colour>& pixels() const { return pixels_; }
  /// Hands the pixels over, leaving the canvas empty.
  std::vector<Colour> release() { return std::move(pixels_); }

 private:
  int width_;
  int height_;
  std::vector<Colour> pixels_;
};

}  // namespace ppp
