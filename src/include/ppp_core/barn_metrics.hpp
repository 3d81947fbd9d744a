#pragma once

#include <limits>
#include <string>
#include <vector>

#include "ppp_core/dpa.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/problem.hpp"

namespace ppp {

/// Most rays or axes BarnOptions accepts for one measure.
constexpr int kMaxBarnRays = 4096;

/// Parameters of BARN's difficulty metrics on a grid (docs/reference/evaluation.md, "BARN metrics"); lengths in cells.
/// Rays start at a cell's centre, ray i of n at angle 2*pi*i/n counter-clockwise from east (north = row - 1).
struct BarnOptions {
  int visibility_rays = 8;       ///< Rays averaged by the visibility (BARN: the 8 king moves).
  int dispersion_rays = 16;      ///< Rays around the circle of the dispersion (BARN: 16).
  double dispersion_radius = 3;  ///< A dispersion ray is blocked when it stops short of this (BARN: 3 cells).
  int dimension_axes = 4;        ///< Axes of the characteristic dimension, axis j at pi*j/axes (BARN: 4).
  double range = std::numeric_limits<double>::infinity();  ///< Every ray and the clearance stop here (BARN: none).
  /// Checks every option. @throws InvalidArgument naming the option when a count is outside [1, kMaxBarnRays] or
  /// dispersion_radius or range is not positive (range may be infinite, dispersion_radius may not).
  void validate() const;
};

/// BARN's five difficulty metrics of one PPP, measured along a route from start to goal.
struct BarnMetrics {
  bool valid = false;                   ///< False when there is no route (goal unreachable); the values are then 0.
  double closest_obstacle = 0;          ///< Mean over route cells of the distance to the nearest obstacle or edge.
  double visibility = 0;                ///< Mean over route cells of the mean length of the visibility rays.
  double dispersion = 0;                ///< Mean over route cells of the blocked/open alternations around the rays.
  double characteristic_dimension = 0;  ///< Mean over route cells of the shortest free chord over the axes.
  double tortuosity = 0;                ///< Route length over the straight-line distance from start to goal.
};

/// BARN's metrics along `route` (cells in order; consecutive cells may be any distance apart). Everything off the
/// grid counts as obstacle; a ray stops where it enters an obstacle cell's interior (grazing a corner does not
/// stop it). @throws InvalidArgument naming the option for bad options, "route" for fewer than two cells, a cell
/// off the grid or on an obstacle, or a route ending where it starts.
BarnMetrics barnMetrics(const Grid& grid, const std::vector<Cell>& route, const BarnOptions& options = {});

/// BARN's metrics along the route of a DPA result the caller already has for `grid` (not valid when the goal is
/// unreachable). @throws InvalidArgument naming the option for bad options.
BarnMetrics barnMetrics(const Grid& grid, const DpaResult& dpa, const BarnOptions& options = {});

/// BARN's metrics of a PPP along the DPA route achieving the fewest turns+advances (not valid when the goal is
/// unreachable). @throws InvalidArgument naming the option for bad options.
BarnMetrics barnMetrics(const Problem& problem, const Grid& grid, const BarnOptions& options = {});

/// Names of BARN's metrics as taxonomic characters, in barnCharacterVector() order: barn_closest_obstacle,
/// barn_visibility, barn_dispersion, barn_characteristic_dimension, barn_tortuosity.
const std::vector<std::string>& barnCharacterNames();

/// The five metrics in barnCharacterNames() order.
std::vector<double> barnCharacterVector(const BarnMetrics& metrics);

}  // namespace ppp
