#pragma once

#include <string>

#include "ppp_core/grid.hpp"

namespace ppp {

/// The shape of a map's obstacles, whatever their place: its obstacle cells cropped to their bounding box, read in
/// the one of the square's 8 symmetries (a quarter turn 0 to 3 times, mirrored or not) whose text is smallest,
/// as "WxH:" and the rows ('#' obstacle, '.' free) joined by '/'; "0x0:" for a map without obstacles. Two maps
/// have the same shape exactly when one's obstacles are the other's moved, mirrored or rotated: how the corpus and
/// the hunting benchmark tell two shrunk traps apart.
std::string obstacleShape(const Grid& grid);

}  // namespace ppp
