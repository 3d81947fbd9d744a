#pragma once

#include <string>
#include <vector>

#include "ppp_core/grid.hpp"

namespace ppp {

/// Largest `.scen` file read (the benchmark's largest hold a few thousand lines).
constexpr std::size_t kMaxScenarioFileBytes = 64u << 20;

/// One line of a MovingAI scenario file (`.scen`, "version 1"): a start/goal pair on a map with its published
/// optimal 8-connected length.
struct MovingAiScenario {
  int bucket = 0;              ///< The benchmark's difficulty bucket (optimal length / 4, rounded down).
  std::string map;             ///< The map's path as written in the file.
  int map_width = 0;           ///< The map's width as written in the file.
  int map_height = 0;          ///< The map's height as written in the file.
  Cell start;                  ///< Start cell (x right, y down, as in the map's rows).
  Cell goal;                   ///< Goal cell.
  double optimal_length = 0;   ///< Published optimal length: 1 per straight move, sqrt(2) per diagonal.
  int line = 0;                ///< The line it was read from (0 when not read from a file).
};

/// Parses the text of a `.scen` file named `source` in errors.
/// @throws ParseError "source:line: field: ..." for a missing or wrong `version` line, a line without nine
/// fields, a non-numeric or negative field, a cell outside the size the line gives, a non-finite length.
std::vector<MovingAiScenario> parseMovingAiScenarios(const std::string& text, const std::string& source);

/// Reads a `.scen` file. @throws IoError, ParseError.
std::vector<MovingAiScenario> readMovingAiScenarios(const std::string& path);

/// The text of a "version 1" `.scen` file of `scenarios`, tab-separated, lengths with 8 decimals (as the
/// benchmark's files).
std::string formatMovingAiScenarios(const std::vector<MovingAiScenario>& scenarios);

/// Writes formatMovingAiScenarios() to `path`, atomically. @throws IoError.
void writeMovingAiScenarios(const std::vector<MovingAiScenario>& scenarios, const std::string& path);

/// The map file of a scenario file's `map` entry: the path as written (relative to the working directory), else a
/// file of the same name beside the `.scen`, else one in `map_dir` (when not empty).
/// @throws IoError naming the scenario file and every place looked.
std::string findScenarioMap(const std::string& scen_path, const std::string& map, const std::string& map_dir);

/// Checks a scenario against its map: the sizes agree, start and goal are free cells and not the same cell.
/// @throws ParseError "source:line: field: ..." naming the scenario's line.
void checkScenarioOnMap(const MovingAiScenario& scenario, const Grid& grid, const std::string& source);

}  // namespace ppp
