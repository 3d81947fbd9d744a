#include "scan_costmap.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>

#include "ppp_core/error.hpp"

namespace ppp {
namespace planners {
namespace {

/// Most cells of a costmap.
constexpr long kMaxCells = 4000000;
/// How much dearer a cell touching the lethal zone is to cross than a free one (falling linearly to 1 at the
/// inflation radius).
constexpr double kInflationWeight = 4;

}  // namespace

ScanCostmap::ScanCostmap(double width, double height, MapPoint origin, double resolution, double radius,
                         double inflation_radius)
    : resolution_(resolution), origin_(origin), radius_(radius), inflation_radius_(inflation_radius) {
  if (!(resolution > 0) || !std::isfinite(resolution)) {
    throw InvalidArgument("costmap_resolution", "expected metres > 0");
  }
  const double cells_x = std::ceil(width / resolution), cells_y = std::ceil(height / resolution);
  if (!(cells_x >= 1 && cells_y >= 1 && cells_x * cells_y <= kMaxCells)) {
    throw InvalidArgument("costmap_resolution", "a map of " + std::to_string(width) + " x " + std::to_string(height) +
                                                    " m in cells of " + std::to_string(resolution) +
                                                    " m: expected 1 to " + std::to_string(kMaxCells) + " cells");
  }
  width_ = static_cast<int>(cells_x);
  height_ = static_cast<int>(cells_y);
  const std::size_t cells = static_cast<std::size_t>(width_) * height_;
  marked_.assign(cells, 0);
  clearance_.assign(cells, std::numeric_limits<double>::infinity());
  cost_.assign(cells, std::numeric_limits<double>::infinity());
  lethal_.assign(cells, 0);
  weight_.assign(cells, 1.0);
}

int ScanCostmap::cellAt(MapPoint point) const {
  const double fx = std::floor((point.x - origin_.x) / resolution_);
  const double fy = std::floor((point.y - origin_.y) / resolution_);
  if (!(fx >= 0 && fy >= 0 && fx < width_ && fy < height_)) return -1;
  return static_cast<int>(fy) * width_ + static_cast<int>(fx);
}

MapPoint ScanCostmap::centre(int cell) const {
  return {origin_.x + (cell % width_ + 0.5) * resolution_, origin_.y + (cell / width_ + 0.5) * resolution_};
}

void ScanCostmap::mark(MapPoint from, const std::vector<MapPoint>& returns) {
  // How near a cell's line a return counts as on it (metres; a LaserScan's ranges are floats), and how far
  // across the line its cell is looked up.
  constexpr double kOnLine = 1e-4, kAcross = 1e-3;
  const auto onLine = [this](double metres) {
    const double lines = metres / resolution_;
    return std::abs(lines - std::round(lines)) * resolution_ < kOnLine;
  };
  const int reach = static_cast<int>(std::ceil(std::max(radius_, inflation_radius_) / resolution_));
  for (const MapPoint& hit : returns) {
    const bool on_column = onLine(hit.x - origin_.x), on_row = onLine(hit.y - origin_.y);
    if (on_column && on_row) continue;
    const double dx = hit.x - from.x, dy = hit.y - from.y;
    const double length = std::hypot(dx, dy);
    if (!(length > 0)) continue;
    MapPoint point{hit.x + kAcross * dx / length, hit.y + kAcross * dy / length};
    if (on_column) point = {hit.x + std::copysign(kAcross, dx), hit.y};
    if (on_row) point = {hit.x, hit.y + std::copysign(kAcross, dy)};
    const int cell = cellAt(point);
    if (cell < 0 || marked_[cell]) continue;
    marked_[cell] = 1;
    changed_ = true;
    const int cx = cell % width_, cy = cell / width_;
    for (int y = std::max(0, cy - reach); y <= std::min(height_ - 1, cy + reach); ++y) {
      for (int x = std::max(0, cx - reach); x <= std::min(width_ - 1, cx + reach); ++x) {
        // From the cell's centre to the marked square.
        const double ex = std::max(0, std::abs(x - cx) * 2 - 1) * 0.5 * resolution_;
        const double ey = std::max(0, std::abs(y - cy) * 2 - 1) * 0.5 * resolution_;
        double& clearance = clearance_[y * width_ + x];
        clearance = std::min(clearance, (x == cx && y == cy) ? 0.0 : std::hypot(ex, ey));
      }
    }
  }
}

void ScanCostmap::plan(MapPoint goal) {
  if (!changed_ && planned_ && goal.x == goal_.x && goal.y == goal_.y) return;
  changed_ = false;
  planned_ = true;
  goal_ = goal;
  std::fill(cost_.begin(), cost_.end(), std::numeric_limits<double>::infinity());
  const int goal_cell = cellAt(goal);
  if (goal_cell < 0) return;
  // Whether each cell is lethal, and its weight (how much dearer it is to cross), once for the whole wavefront.
  const double band = inflation_radius_ - radius_;  // metres of inflation beyond the lethal zone
  for (std::size_t cell = 0; cell < weight_.size(); ++cell) {
    lethal_[cell] = clearance_[cell] < radius_ || marked_[cell];
    weight_[cell] = band > 0 ? 1 + kInflationWeight * std::max(0.0, 1 - (clearance_[cell] - radius_) / band) : 1.0;
  }
  const auto lethal = [this](int cell) { return lethal_[cell] != 0; };
  const auto weight = [this](int cell) { return weight_[cell]; };
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  cost_[goal_cell] = 0;
  open.push({0, goal_cell});
  while (!open.empty()) {
    const auto [c, cell] = open.top();
    open.pop();
    if (c > cost_[cell]) continue;
    const int x = cell % width_, y = cell / width_;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= width_ || ny >= height_) continue;
        const int next = ny * width_ + nx;
        if (lethal(next)) continue;
        if (dx != 0 && dy != 0 && (lethal(y * width_ + nx) || lethal(ny * width_ + x))) continue;
        const double step = resolution_ * (dx != 0 && dy != 0 ? M_SQRT2 : 1.0) * 0.5 * (weight(cell) + weight(next));
        if (c + step < cost_[next]) {
          cost_[next] = c + step;
          open.push({c + step, next});
        }
      }
    }
  }
}

double ScanCostmap::distance(MapPoint point) const {
  const int cell = cellAt(point);
  if (cell < 0) return std::numeric_limits<double>::infinity();
  double best = std::numeric_limits<double>::infinity();
  const int cx = cell % width_, cy = cell / width_;
  for (int y = std::max(0, cy - 1); y <= std::min(height_ - 1, cy + 1); ++y) {
    for (int x = std::max(0, cx - 1); x <= std::min(width_ - 1, cx + 1); ++x) {
      const MapPoint c = centre(y * width_ + x);
      best = std::min(best, cost_[y * width_ + x] + std::hypot(c.x - point.x, c.y - point.y));
    }
  }
  return best;
}

}  // namespace planners
}  // namespace ppp
