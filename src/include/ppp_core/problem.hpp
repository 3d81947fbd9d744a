#pragma once

#include <string>
#include <utility>
#include <vector>

#include "ppp_core/grid.hpp"

namespace ppp {

/// The shapes an obstacle descriptor can paint.
enum class Shape {
  HorizontalBar,  ///< `length` cells to the right of the anchor.
  VerticalBar,    ///< `length` cells down from the anchor.
  DiagonalDown,   ///< `length` cells from the anchor towards the bottom-right.
  DiagonalUp,     ///< `length` cells from the anchor towards the top-right.
  Block,          ///< A `length` (wide) × `height` (tall) rectangle whose top-left is the anchor.
};

/// All shapes, in the order of the enum.
constexpr Shape kAllShapes[] = {Shape::HorizontalBar, Shape::VerticalBar, Shape::DiagonalDown, Shape::DiagonalUp,
                                Shape::Block};

/// The shape's keyword in `.ppp` files (hbar, vbar, diag_down, diag_up, block).
const char* shapeName(Shape shape);
/// Parses a shape keyword; returns false when it is not one.
bool parseShape(const std::string& name, Shape* shape);

/// One gene of the chromosome: a shape placed on the grid. Cells beyond the grid edge are clipped.
struct Obstacle {
  Shape shape = Shape::HorizontalBar;  ///< What is painted.
  int x = 0;                           ///< Anchor column (must be on the grid).
  int y = 0;                           ///< Anchor row (must be on the grid).
  int length = 1;                      ///< Cells along a bar, or a block's width.
  int height = 1;                      ///< A block's height; always 1 for bars.
  /// Descriptors are equal when every field is.
  friend bool operator==(const Obstacle& a, const Obstacle& b) {
    return a.shape == b.shape && a.x == b.x && a.y == b.y && a.length == b.length && a.height == b.height;
  }
};

/// Largest accepted obstacle budget (descriptors per chromosome).
constexpr int kMaxObstacleBudget = 1 << 20;

/// Ordered key/value annotations carried with a PPP (fitness, seed, characters...).
using Metadata = std::vector<std::pair<std::string, std::string>>;

/// A path-planning problem: size, start, goal and the obstacle chromosome; the grid is decoded from it.
struct Problem {
  int width = 20;               ///< Columns.
  int height = 20;              ///< Rows.
  Cell start{0, 0};             ///< Start cell, protected from obstacles.
  Cell goal{19, 19};            ///< Goal cell, protected from obstacles.
  int max_obstacles = 10;       ///< Obstacle budget: the most descriptors a chromosome may hold.
  std::vector<Obstacle> obstacles;  ///< The chromosome, painted in order.
  Metadata metadata;            ///< Free-form annotations, written to and read from files.

  /// A problem with default start (top-left) and goal (bottom-right) for the size; no obstacles.
  static Problem empty(int width, int height, int max_obstacles);
  /// Problems are equal when every field, metadata included, is.
  friend bool operator==(const Problem& a, const Problem& b);
};

/// Every cell a descriptor covers on a grid of the given size, clipped to the grid.
std::vector<Cell> obstacleCells(const Obstacle& obstacle, int width, int height);

/// Checks one descriptor against the grid size. @throws InvalidArgument naming `what`.
void validateObstacle(const Obstacle& obstacle, int width, int height, const std::string& what);

/// Checks size, start, goal, budget and every descriptor. @throws InvalidArgument naming the field.
void validateProblem(const Problem& problem);

/// Paints the descriptors onto an empty grid, skipping the protected start and goal cells.
Grid decodeGrid(const Problem& problem);

/// The problem painting exactly `grid` (the inverse of decodeGrid for an imported map): one hbar per horizontal run
/// of obstacle cells, row by row, max_obstacles their count, no metadata.
/// @throws InvalidArgument naming the field for a bad size, a start or goal off the grid, on an obstacle or equal,
/// and "obstacles" when the grid holds more than kMaxObstacleBudget runs (checked as they are collected).
Problem problemFromGrid(const Grid& grid, Cell start, Cell goal);

/// The value stored under `key`, or nullptr.
const std::string* findMetadata(const Metadata& metadata, const std::string& key);
/// Sets `key` to `value`, replacing an existing entry in place or appending a new one.
void setMetadata(Metadata* metadata, const std::string& key, const std::string& value);

}  // namespace ppp
