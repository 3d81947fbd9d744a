#pragma once

#include <string>
#include <vector>

#include "ppp_core/evaluation.hpp"
#include "ppp_core/grid.hpp"

namespace ppp {
namespace cli {

/// A grid size given as "WxH".
struct Size {
  int width = 0;   ///< Columns.
  int height = 0;  ///< Rows.
};

/// Parses "WxH" (e.g. "20x20"). @throws InvalidArgument naming `option`.
Size parseSize(const std::string& text, const std::string& option);

/// Parses "X,Y". @throws InvalidArgument naming `option`.
Cell parseCell(const std::string& text, const std::string& option);

/// Applies "NAME=VALUE" overrides to `base` weights. @throws InvalidArgument listing the valid names.
DifficultyWeights parseWeights(const std::vector<std::string>& assignments, const DifficultyWeights& base = {});

}  // namespace cli
}  // namespace ppp
