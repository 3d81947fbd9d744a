#include "ppp_core/segment_walk.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <string>

#include "ppp_core/error.hpp"

namespace ppp {

namespace {

/// Coordinates are refused beyond this many cells from the origin (16 times the largest grid side), which
/// bounds the walk's length and keeps every cell index an int.
constexpr double kMaxCoordinate = 16.0 * kMaxGridSide;

int checkedFloor(double value, const char* name) {
  if (!std::isfinite(value) || std::fabs(value) > kMaxCoordinate) {
    throw InvalidArgument(std::string("segment ") + name, "expected a finite coordinate within " +
                                                              std::to_string(static_cast<int>(kMaxCoordinate)) +
                                                              " cells of the origin, got " + std::to_string(value));
  }
  return static_cast<int>(std::floor(value));
}

/// Sign (-1, 0 or 1) of the exact sum of the terms. Shewchuk's grow-expansion: every addition keeps its
/// rounding error (Knuth's two-sum) as a further component; the components stay non-overlapping and ordered
/// by magnitude, so the largest non-zero one carries the sign of the whole sum.
template <std::size_t N>
int exactSumSign(const std::array<double, N>& terms) {
  std::array<double, N> expansion{};
  std::size_t size = 0;
  for (const double term : terms) {
    double carry = term;
    for (std::size_t i = 0; i < size; ++i) {
      const double sum = carry + expansion[i];
      const double rounded_part = sum - carry;
      expansion[i] = (carry - (sum - rounded_part)) + (expansion[i] - rounded_part);
      carry = sum;
    }
    expansion[size++] = carry;
  }
  for (std::size_t i = size; i-- > 0;) {
    if (expansion[i] != 0.0) return expansion[i] > 0.0 ? 1 : -1;
  }
  return 0;
}

/// Exact sign of (cx - x0)(y1 - y0) - (cy - y0)(x1 - x0): which side of the line through the segment the
/// corner (cx, cy) lies on. A rounded evaluation decides when it is clearly away from zero (five roundings
/// err by less than 5 * 2^-53 * (|left| + |right|)); otherwise the six products of the expanded form, each
/// split exactly into a rounded value and its fma remainder, are summed exactly. Exact unless a product
/// underflows (non-zero coordinates below about 1e-140 in magnitude).
int cornerSide(double x0, double y0, double x1, double y1, double cx, double cy) {
  const double left = (cx - x0) * (y1 - y0);
  const double right = (cy - y0) * (x1 - x0);
  const double rounded = left - right;
  const double error_bound = 5.0 * std::ldexp(1.0, -53) * (std::fabs(left) + std::fabs(right));
  if (rounded > error_bound) return 1;
  if (rounded < -error_bound) return -1;
  const std::array<std::array<double, 2>, 6> products{{{cx, y1}, {-cx, y0}, {-cy, x1}, {cy, x0}, {x1, y0}, {-x0, y1}}};
  std::array<double, 12> terms{};
  for (std::size_t i = 0; i < products.size(); ++i) {
    const double product = products[i][0] * products[i][1];
    terms[2 * i] = product;
    terms[2 * i + 1] = std::fma(products[i][0], products[i][1], -product);
  }
  return exactSumSign(terms);
}

}  // namespace

std::vector<Cell> walkSegment(double x0, double y0, double x1, double y1) {
  Cell cell{checkedFloor(x0, "x0"), checkedFloor(y0, "y0")};
  const Cell last{checkedFloor(x1, "x1"), checkedFloor(y1, "y1")};
  const int step_x = x1 > x0 ? 1 : -1;
  const int step_y = y1 > y0 ? 1 : -1;
  int x_steps = std::abs(last.x - cell.x);
  int y_steps = std::abs(last.y - cell.y);

  std::vector<Cell> cells;
  cells.reserve(static_cast<std::size_t>(x_steps + y_steps + 1));
  cells.push_back(cell);
  while (x_steps + y_steps > 0) {
    bool x_first = y_steps == 0;
    if (x_steps > 0 && y_steps > 0) {
      // The segment leaves the cell through the corner ahead of it or through one of the two sides meeting
      // there; which one follows from the corner's side of the segment. Through the corner itself: x first.
      const double corner_x = cell.x + (step_x > 0 ? 1 : 0);
      const double corner_y = cell.y + (step_y > 0 ? 1 : 0);
      x_first = step_x * step_y * cornerSide(x0, y0, x1, y1, corner_x, corner_y) <= 0;
    }
    if (x_first) {
      cell.x += step_x;
      --x_steps;
    } else {
      cell.y += step_y;
      --y_steps;
    }
    cells.push_back(cell);
  }
  return cells;
}

std::vector<Cell> walkMapSegment(const MapFrame& frame, double x0, double y0, double x1, double y1) {
  const auto grid_x = [&frame](double x) { return x / frame.resolution; };
  const auto grid_y = [&frame](double y) { return frame.height - y / frame.resolution; };
  return walkSegment(grid_x(x0), grid_y(y0), grid_x(x1), grid_y(y1));
}

}  // namespace ppp
