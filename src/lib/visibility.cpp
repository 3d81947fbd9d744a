#include "ppp_core/visibility.hpp"

#include <algorithm>
#include <cstdlib>

namespace ppp {

namespace {

// A cone is described by where "major" (distance along the cone's axis) and "minor" (offset across it) go.
struct Cone {
  int major_dx, major_dy, minor_dx, minor_dy;
};
constexpr Cone kCones[4] = {{1, 0, 0, 1}, {-1, 0, 0, 1}, {0, 1, 1, 0}, {0, -1, 1, 0}};

Cell coneCell(Cell origin, const Cone& cone, int major, int minor) {
  return Cell{origin.x + cone.major_dx * major + cone.minor_dx * minor,
              origin.y + cone.major_dy * major + cone.minor_dy * minor};
}

// a/b < c/d for positive denominators.
inline bool less(std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d) { return a * d < c * b; }

}  // namespace

namespace {

/// Calls `visit(cell)` for every cell whose interior the open segment between the centres of `from` and `to`
/// crosses (ends excluded, cells off the grid included), nearest first; stops early when `visit` returns false.
template <typename Visit>
bool forEachCellCrossed(Cell from, Cell to, Visit visit) {
  const int dx = to.x - from.x;
  const int dy = to.y - from.y;
  const bool x_major = std::abs(dx) >= std::abs(dy);
  const int d = x_major ? std::abs(dx) : std::abs(dy);  // distance along the major axis
  const int m = x_major ? dy : dx;  // signed offset across the major axis, |m| <= d
  const int major_sign = (x_major ? dx : dy) >= 0 ? 1 : -1;
  for (int k = 1; k < d; ++k) {
    // In doubled coordinates the segment crosses row band (2k-1, 2k+1) with minor in (lo, hi) (times 1/d).
    const std::int64_t a = static_cast<std::int64_t>(m) * (2 * k - 1);
    const std::int64_t b = static_cast<std::int64_t>(m) * (2 * k + 1);
    const std::int64_t lo = std::min(a, b);
    const std::int64_t hi = std::max(a, b);
    const int centre = static_cast<int>((static_cast<std::int64_t>(m) * k) / d);
    for (int mm = centre - 1; mm <= centre + 1; ++mm) {
      // Open interval (lo, hi)/d meets the cell's open band (2mm-1, 2mm+1); lo == hi means a line at lo/d.
      const bool crosses =
          lo < static_cast<std::int64_t>(2 * mm + 1) * d && hi > static_cast<std::int64_t>(2 * mm - 1) * d;
      if (!crosses) continue;
      const int major_offset = k * major_sign;
      const Cell c = x_major ? Cell{from.x + major_offset, from.y + mm} : Cell{from.x + mm, from.y + major_offset};
      if (!visit(c)) return false;
    }
  }
  return true;
}

}  // namespace

bool lineOfSight(const Grid& grid, Cell from, Cell to) {
  return forEachCellCrossed(from, to, [&](Cell c) { return !(grid.contains(c) && grid.isObstacle(c)); });
}

std::vector<Cell> cellsCrossed(Cell from, Cell to) {
  std::vector<Cell> cells;
  forEachCellCrossed(from, to, [&](Cell c) {
    cells.push_back(c);
    return true;
  });
  return cells;
}

void VisibilitySolver::sweepCone(const Grid& grid, Cell v, int cone_index) {
  const Cone& cone = kCones[cone_index];
  shadows_.clear();
  for (int d = 1;; ++d) {
    // Range of minor offsets whose cells are on the grid in this row.
    const Cell axis = coneCell(v, cone, d, 0);
    if (!grid.contains(axis)) break;
    int lo_m = -d;
    int hi_m = d;
    while (lo_m <= hi_m && !grid.contains(coneCell(v, cone, d, lo_m))) ++lo_m;
    while (hi_m >= lo_m && !grid.contains(coneCell(v, cone, d, hi_m))) --hi_m;
    // Cells whose centre slope m/d lies strictly inside a shadow of a nearer row are hidden.
    std::size_t s = 0;
    row_shadows_.clear();
    const std::int64_t two_d = 2 * static_cast<std::int64_t>(d);
    for (int m = lo_m; m <= hi_m; ++m) {
      while (s < shadows_.size() && !less(m, d, shadows_[s].hi_num, shadows_[s].hi_den)) ++s;
      const bool hidden = s < shadows_.size() && less(shadows_[s].lo_num, shadows_[s].lo_den, m, d);
      const Cell c = coneCell(v, cone, d, m);
      const int index = grid.index(c);
      if (!hidden) visible_[index] = 1;
      if (grid.cells()[index] == 0) continue;
      // The obstacle's angular extent: corners (2d +- 1, 2m +- 1) in doubled coordinates.
      Shadow shadow;
      if (m > 0) {
        shadow = {2 * m - 1, two_d + 1, 2 * m + 1, two_d - 1};
      } else if (m < 0) {
        shadow = {2 * m - 1, two_d - 1, 2 * m + 1, two_d + 1};
      } else {
        shadow = {-1, two_d - 1, 1, two_d - 1};
      }
      if (!row_shadows_.empty() && less(shadow.lo_num, shadow.lo_den, row_shadows_.back().hi_num,
                                        row_shadows_.back().hi_den)) {
        row_shadows_.back().hi_num = shadow.hi_num;
        row_shadows_.back().hi_den = shadow.hi_den;
      } else {
        row_shadows_.push_back(shadow);
      }
    }
    if (row_shadows_.empty()) continue;
    // Merge the row's shadows into the sorted, overlap-free list (touching intervals stay apart).
    merged_.clear();
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < shadows_.size() || j < row_shadows_.size()) {
      const bool take_old = j >= row_shadows_.size() ||
                            (i < shadows_.size() && less(shadows_[i].lo_num, shadows_[i].lo_den,
                                                         row_shadows_[j].lo_num, row_shadows_[j].lo_den));
      const Shadow& next = take_old ? shadows_[i++] : row_shadows_[j++];
      if (!merged_.empty() && less(next.lo_num, next.lo_den, merged_.back().hi_num, merged_.back().hi_den)) {
        if (less(merged_.back().hi_num, merged_.back().hi_den, next.hi_num, next.hi_den)) {
          merged_.back().hi_num = next.hi_num;
          merged_.back().hi_den = next.hi_den;
        }
      } else {
        merged_.push_back(next);
      }
    }
    shadows_.swap(merged_);
  }
}

int VisibilitySolver::solve(const Grid& grid, Cell viewpoint) {
  visible_.assign(static_cast<std::size_t>(grid.size()), 0);
  visible_[grid.index(viewpoint)] = 1;
  for (int cone = 0; cone < 4; ++cone) sweepCone(grid, viewpoint, cone);
  int count = 0;
  for (std::uint8_t v : visible_) count += v;
  return count;
}

double visibilityFraction(const Grid& grid, Cell viewpoint) {
  VisibilitySolver solver;
  return static_cast<double>(solver.solve(grid, viewpoint)) / grid.size();
}

}  // namespace ppp
