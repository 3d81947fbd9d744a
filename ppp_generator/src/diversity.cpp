#include "ppp_generator/diversity.hpp"

#include <algorithm>
#include <string>

#include "ppp_core/error.hpp"

namespace ppp {
namespace generator {

namespace {

/// Differing cells of two grids of the same size.
long differingCells(const Grid& a, const Grid& b) {
  const auto& x = a.cells();
  const auto& y = b.cells();
  long count = 0;
  for (std::size_t i = 0; i < x.size(); ++i) count += (x[i] != 0) != (y[i] != 0) ? 1 : 0;
  return count;
}

void checkSameSize(const Grid& a, const Grid& b) {
  if (a.width() != b.width() || a.height() != b.height()) {
    throw InvalidArgument("grids", "expected grids of one size, got " + std::to_string(a.width()) + "x" +
                                       std::to_string(a.height()) + " and " + std::to_string(b.width()) + "x" +
                                       std::to_string(b.height()));
  }
}

}  // namespace

double cellDifference(const Grid& a, const Grid& b) {
  checkSameSize(a, b);
  return static_cast<double>(differingCells(a, b)) / static_cast<double>(a.size());
}

DiversityFigures measureDiversity(const std::vector<Grid>& grids) {
  DiversityFigures figures;
  figures.nearest.assign(grids.size(), grids.size() < 2 ? 0.0 : 1.0);
  if (grids.size() < 2) return figures;
  double obstacles = 0.0;
  for (const Grid& g : grids) {
    checkSameSize(grids[0], g);
    obstacles += static_cast<double>(g.obstacleCount());
  }
  double total = 0.0;
  for (std::size_t i = 0; i < grids.size(); ++i) {
    for (std::size_t j = i + 1; j < grids.size(); ++j) {
      const double d = cellDifference(grids[i], grids[j]);
      total += d;
      figures.nearest[i] = std::min(figures.nearest[i], d);
      figures.nearest[j] = std::min(figures.nearest[j], d);
    }
  }
  const double density = obstacles / (static_cast<double>(grids.size()) * static_cast<double>(grids[0].size()));
  const double expected = 2.0 * density * (1.0 - density);
  const double pairs = static_cast<double>(grids.size()) * static_cast<double>(grids.size() - 1) / 2.0;
  figures.diversity = expected > 0.0 ? total / pairs / expected : 0.0;
  return figures;
}

double setDiversity(const std::vector<Grid>& grids) { return measureDiversity(grids).diversity; }

std::vector<double> nearestDifferences(const std::vector<Grid>& grids) { return measureDiversity(grids).nearest; }

}  // namespace generator
}  // namespace ppp
