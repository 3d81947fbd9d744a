#pragma once

#include <functional>

#include "ppp_core/problem.hpp"
#include "ppp_core/stop.hpp"

namespace ppp {

/// The one question a shrink asks of a candidate PPP: is it valid (its goal reachable, for the robot's body)
/// and does it still fail the same way?
using StillFails = std::function<bool(const Problem&)>;

/// What a shrink removes.
enum class ShrinkUnits {
  /// The chromosome: descriptors removed by delta debugging (halves, quarters, ... then single ones), then each
  /// remaining descriptor made smaller a cell at a time (a bar shorter at either end, a block a row or column
  /// narrower on any side).
  Descriptors,
  /// The decoded grid's obstacle cells, for maps imported without descriptors (map_server, MovingAI): its
  /// 4-connected obstacle components removed by delta debugging, then single cells. The result is written as
  /// problemFromGrid() writes a grid.
  Cells,
};

/// A shrunk PPP and what it took.
struct ShrinkResult {
  Problem problem;      ///< The smallest PPP found (the input's size, start, goal and metadata).
  int evaluations = 0;  ///< Candidates judged.
};

/// Shrinks `problem`, for which `still_fails` holds, to a PPP for which it still holds and which is 1-minimal:
/// with ShrinkUnits::Descriptors, removing any one of its descriptors, or making any one a cell smaller, makes
/// `still_fails` false; with ShrinkUnits::Cells, removing any one obstacle cell does. Deterministic: the same
/// problem and answers give the same result. @throws InvalidArgument naming "problem" when `still_fails` does
/// not hold for `problem` itself; Interrupted when `stop`, asked before each candidate, says stop.
ShrinkResult shrinkProblem(const Problem& problem, const StillFails& still_fails, ShrinkUnits units,
                           const StopCheck& stop = {});

/// The descriptors one cell smaller than `obstacle`, in the order a shrink tries them (none for a single cell).
std::vector<Obstacle> smallerObstacles(const Obstacle& obstacle);

}  // namespace ppp
