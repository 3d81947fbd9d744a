#pragma once

#include "ppp_core/grid.hpp"

namespace ppp {

/// Mean over rows of (longest run of free cells in the row) / width.
double horizontalOpenness(const Grid& grid);

/// Mean over columns of (longest run of free cells in the column) / height.
double verticalOpenness(const Grid& grid);

}  // namespace ppp
