#pragma once

#include <vector>

#include "ppp_core/grid.hpp"

namespace ppp {
namespace generator {

/// Share of cells (0..1) in which two grids of the same size differ. @throws InvalidArgument on a size mismatch.
double cellDifference(const Grid& a, const Grid& b);

/// How different the maps of a set are (docs/reference/evaluation.md, "Set diversity"): the mean over all pairs of
/// cellDifference, divided by 2d(1-d), the expected difference of two independent maps of the set's mean obstacle
/// density d. 1.0 means as different as independent maps; near 0, copies of one layout. 0 for fewer than two grids or
/// when d is 0 or 1 (every map is then the same). @throws InvalidArgument when the grids differ in size.
double setDiversity(const std::vector<Grid>& grids);

/// For each grid, cellDifference to the most similar other grid of the set (0 for a set of one).
std::vector<double> nearestDifferences(const std::vector<Grid>& grids);

/// Both figures of a set, from one pass over its pairs.
struct DiversityFigures {
  double diversity = 0;         ///< setDiversity of the grids.
  std::vector<double> nearest;  ///< nearestDifferences of the grids.
};

/// setDiversity and nearestDifferences at once. @throws InvalidArgument when the grids differ in size.
DiversityFigures measureDiversity(const std::vector<Grid>& grids);

}  // namespace generator
}  // namespace ppp
