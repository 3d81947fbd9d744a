#pragma once

#include <vector>

#include "ppp_core/grid.hpp"

namespace ppp {

// A robot with a body (docs/how-to/robot-with-a-body.md): a disc of `robot_radius` cells centred in the cell it
// stands on. It may stand where the disc overlaps no obstacle cell and stays on the map; that set of cells is its
// configuration space.

/// Largest robot radius, in cells.
constexpr double kMaxRobotRadius = 64;

/// True when a disc of `radius` cells fits inside its own cell (radius <= 0.5): the point robot of the
/// dissertation, whose configuration space is the grid itself.
bool isPointRobot(double radius);

/// The offsets (dx, dy) of the cells a disc of `radius` centred in cell (0, 0) overlaps, (0, 0) included: those
/// whose square comes nearer to the centre than `radius` (a disc of radius 1 covers the 3x3 block around it).
std::vector<Cell> footprintOffsets(double radius);

/// The grid a robot of `radius` moves on: `grid` itself for a point robot (nothing is copied), else its
/// configuration space, made in `space`.
const Grid& motionGrid(const Grid& grid, double radius, Grid* space);

/// The configuration space of a disc of `radius` on `grid`: a cell is free when every cell of its footprint is a
/// free cell of the map. For a point robot, `grid` itself.
Grid configurationSpace(const Grid& grid, double radius);

}  // namespace ppp
