#pragma once

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace ppp {

/// A cell position: x to the right, y down (file and grid convention).
struct Cell {
  int x = 0;  ///< Column, 0 at the left.
  int y = 0;  ///< Row, 0 at the top.
  /// Cells are equal when both coordinates are.
  friend bool operator==(const Cell& a, const Cell& b) { return a.x == b.x && a.y == b.y; }
  /// Negation of ==.
  friend bool operator!=(const Cell& a, const Cell& b) { return !(a == b); }
};

/// The Manhattan distance between two cells: the fewest 4-connected moves between them on an empty grid.
inline int manhattanDistance(Cell a, Cell b) { return std::abs(a.x - b.x) + std::abs(a.y - b.y); }

/// A cell as messages write it: "(x, y)".
std::string cellText(Cell c);

/// Smallest accepted grid side, in cells.
constexpr int kMinGridSide = 2;
/// Largest accepted grid side, in cells: sizes are checked against it before anything is allocated.
constexpr int kMaxGridSide = 4096;

/// A W×H occupancy grid of free and obstacle cells, stored row-major with y down.
class Grid {
 public:
  /// An empty 0×0 grid.
  Grid() = default;
  /// An all-free grid. @throws InvalidArgument when a side is outside [kMinGridSide, kMaxGridSide].
  Grid(int width, int height);

  /// Number of columns.
  int width() const { return width_; }
  /// Number of rows.
  int height() const { return height_; }
  /// Number of cells.
  int size() const { return width_ * height_; }
  /// True when the cell lies on the grid.
  bool contains(Cell c) const { return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_; }
  /// Row-major index of an on-grid cell.
  int index(Cell c) const { return c.y * width_ + c.x; }
  /// The cell at a row-major index.
  Cell cellAt(int index) const { return Cell{index % width_, index / width_}; }
  /// True when the on-grid cell is an obstacle.
  bool isObstacle(Cell c) const { return cells_[index(c)] != 0; }
  /// True when the cell is on the grid and free.
  bool isFree(Cell c) const { return contains(c) && cells_[index(c)] == 0; }
  /// Marks an on-grid cell as obstacle (true) or free (false).
  void setObstacle(Cell c, bool obstacle) { cells_[index(c)] = obstacle ? 1 : 0; }
  /// Number of obstacle cells.
  int obstacleCount() const;
  /// Raw row-major cells, 1 = obstacle, 0 = free.
  const std::vector<std::uint8_t>& cells() const { return cells_; }
  /// FNV-1a hash of the cells (equal grids of one size hash equally; used to find copies and derive seeds).
  std::uint64_t hash() const;
  /// Grids are equal when sizes and every cell agree.
  friend bool operator==(const Grid& a, const Grid& b) {
    return a.width_ == b.width_ && a.height_ == b.height_ && a.cells_ == b.cells_;
  }
  /// Negation of ==.
  friend bool operator!=(const Grid& a, const Grid& b) { return !(a == b); }

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> cells_;
};

/// Checks a requested grid size before allocation. @throws InvalidArgument naming `what` when out of range.
void validateGridSize(int width, int height, const char* what = "size");

}  // namespace ppp
