#pragma once

#include <cstddef>
#include <string>

#include "ppp_core/map_yaml.hpp"
#include "ppp_core/problem.hpp"

namespace ppp {

// MovingAI grid benchmark maps (Sturtevant, https://movingai.com/benchmarks/formats.html):
//   type octile / height H / width W / map, then H rows of W terrain characters.

/// Largest `.map` file the reader accepts, checked before reading it.
constexpr std::size_t kMaxMovingAiMapBytes = 64u << 20;

/// The `.map` text of a problem: `type octile`, its height and width, `map`, then a row per grid row, '.' for a
/// free cell and '@' for an obstacle. The format holds neither start, goal, descriptors nor metadata.
/// @throws InvalidArgument for an invalid problem.
std::string formatMovingAiMap(const Problem& problem);

/// Writes formatMovingAiMap() to `path`, atomically. @throws InvalidArgument, IoError.
void writeMovingAiMap(const Problem& problem, const std::string& path);

/// Reads MovingAI `.map` text; `source` names the file in errors. The header lines must be `type octile`,
/// `height H`, `width W` and `map`, in that order, sides in [kMinGridSide, kMaxGridSide]; then exactly H rows of
/// W characters (lines end in \n or \r\n; blank lines may follow). Terrain '.', 'G' and 'S' (swamp) are free;
/// '@', 'O', 'T' and 'W' are obstacles; any other character is an error. Every horizontal run of obstacle cells
/// becomes one hbar descriptor, max_obstacles is their count. Start and goal come from `options`, else they are
/// the first and the last free cell in row-major order; an unreachable goal is read as it is (as for .ppp and
/// map_server maps; `ppp evaluate` reports it).
/// @throws ParseError "<source>:<line>: <field>: <what>" for bad content or a start or goal on an obstacle,
/// InvalidArgument when an option's start or goal lies outside the map or they are equal.
Problem parseMovingAiMap(const std::string& text, const std::string& source, const MapImportOptions& options = {});

/// Reads a MovingAI `.map` file as parseMovingAiMap() does. @throws IoError and what parseMovingAiMap() throws.
Problem readMovingAiMap(const std::string& path, const MapImportOptions& options = {});

}  // namespace ppp
