#include "ppp_core/movingai_map.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/line_cursor.hpp"
#include "ppp_core/text_file.hpp"

namespace ppp {

namespace {

/// Lines before the first row: type, height, width and map.
constexpr int kHeaderLines = 4;
/// Terrain written for a free cell.
constexpr char kFreeTerrain = '.';
/// Terrain written for an obstacle cell.
constexpr char kObstacleTerrain = '@';
/// The terrain characters a map may hold, for error messages.
constexpr const char* kTerrainChoices = "'.', 'G', 'S' (free) or '@', 'O', 'T', 'W' (obstacle)";

/// Classifies a terrain character; false when it is not one.
bool readTerrain(char terrain, bool* obstacle) {
  switch (terrain) {
    case '.':
    case 'G':
    case 'S':
      *obstacle = false;
      return true;
    case '@':
    case 'O':
    case 'T':
    case 'W':
      *obstacle = true;
      return true;
    default:
      return false;
  }
}

/// The value of the next line, which must read "<key> <value>".
std::string_view headerValue(LineCursor& cursor, const std::string& key, const std::string& usage) {
  const std::string_view line = cursor.require(key, "'" + usage + "'");
  const std::vector<std::string_view> fields = splitFields(line);
  if (fields.empty() || fields[0] != key) {
    cursor.fail(key, "expected '" + usage + "' (a MovingAI map begins with the lines type, height, width and map, " +
                         "in that order), got " + quotedExcerpt(line));
  }
  if (fields.size() != 2) cursor.fail(key, "expected '" + usage + "', got " + quotedExcerpt(line));
  return fields[1];
}

/// A side of the map from its header line: a positive integer within the grid sizes the core handles.
int headerSide(LineCursor& cursor, const std::string& key, const std::string& usage) {
  const std::string_view value = headerValue(cursor, key, usage);
  const bool digits = std::all_of(value.begin(), value.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits || value.find_first_not_of('0') == std::string_view::npos) {
    cursor.fail(key, "expected a positive integer, got " + quotedExcerpt(value));
  }
  int side = 0;
  const auto result = std::from_chars(value.data(), value.data() + value.size(), side);
  if (result.ec != std::errc() || side < kMinGridSide || side > kMaxGridSide) {
    cursor.fail(key, "expected a side in [" + std::to_string(kMinGridSide) + ", " + std::to_string(kMaxGridSide) +
                         "] cells, got " + quotedExcerpt(value));
  }
  return side;
}

/// The grid the rows after the header draw; only blank lines may follow them.
Grid readRows(LineCursor& cursor, int width, int height) {
  Grid grid(width, height);
  const std::string rows = std::to_string(height) + " rows (the height)";
  for (int y = 0; y < height; ++y) {
    const std::string_view row = cursor.require("map", rows + ", got " + std::to_string(y));
    if (row.size() != static_cast<std::size_t>(width)) {
      cursor.fail("map", "row " + std::to_string(y) + " has " + std::to_string(row.size()) + " characters, expected " +
                             std::to_string(width) + " (the width)");
    }
    for (int x = 0; x < width; ++x) {
      bool obstacle = false;
      if (!readTerrain(row[static_cast<std::size_t>(x)], &obstacle)) {
        cursor.fail("map", "unknown terrain character " + quotedExcerpt(row.substr(static_cast<std::size_t>(x), 1)) +
                               " at column " + std::to_string(x + 1) + ", cell " + cellText(Cell{x, y}) +
                               "; expected " + kTerrainChoices);
      }
      grid.setObstacle(Cell{x, y}, obstacle);
    }
  }
  std::string_view extra;
  while (cursor.next(&extra)) {
    if (!splitFields(extra).empty()) cursor.fail("map", "a row beyond the " + rows + ": " + quotedExcerpt(extra));
  }
  return grid;
}

/// The first (or the last) free cell in row-major order; none when every cell is an obstacle.
std::optional<Cell> freeCell(const Grid& grid, bool last) {
  const std::vector<std::uint8_t>& cells = grid.cells();
  if (last) {
    const auto found = std::find(cells.rbegin(), cells.rend(), 0);
    if (found == cells.rend()) return std::nullopt;
    return grid.cellAt(static_cast<int>(cells.rend() - found) - 1);
  }
  const auto found = std::find(cells.begin(), cells.end(), 0);
  if (found == cells.end()) return std::nullopt;
  return grid.cellAt(static_cast<int>(found - cells.begin()));
}

/// The start or goal: `option` when given, which must be a free cell of the map, else `fallback`.
Cell endpoint(const std::optional<Cell>& option, const std::optional<Cell>& fallback, const std::string& name,
              const Grid& grid, const std::string& source) {
  if (!option) {
    if (!fallback) throw ParseError(source, 0, name, "the map has no free cell");
    return *fallback;
  }
  const Cell c = *option;
  if (!grid.contains(c)) {
    throw InvalidArgument(name, "cell " + cellText(c) + " is outside the " + std::to_string(grid.width()) + "x" +
                                    std::to_string(grid.height()) + " map " + source);
  }
  if (grid.isObstacle(c)) {
    throw ParseError(source, kHeaderLines + 1 + c.y, name,
                     "the " + name + " cell " + cellText(c) + " is an obstacle; choose a free cell");
  }
  return c;
}

}  // namespace

std::string formatMovingAiMap(const Problem& problem) {
  validateProblem(problem);
  const Grid grid = decodeGrid(problem);
  std::string out =
      "type octile\nheight " + std::to_string(grid.height()) + "\nwidth " + std::to_string(grid.width()) + "\nmap\n";
  out.reserve(out.size() + static_cast<std::size_t>(grid.width() + 1) * static_cast<std::size_t>(grid.height()));
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) out.push_back(grid.isObstacle(Cell{x, y}) ? kObstacleTerrain : kFreeTerrain);
    out.push_back('\n');
  }
  return out;
}

void writeMovingAiMap(const Problem& problem, const std::string& path) {
  writeFileAtomically(path, formatMovingAiMap(problem));
}

Problem parseMovingAiMap(const std::string& text, const std::string& source, const MapImportOptions& options) {
  if (text.empty()) throw ParseError(source, 1, "type", "empty file; expected 'type octile' on the first line");
  LineCursor cursor(text, source);
  const std::string_view type = headerValue(cursor, "type", "type octile");
  if (type != "octile") {
    cursor.fail("type", "expected 'octile', the MovingAI grid map type, got " + quotedExcerpt(type));
  }
  const int height = headerSide(cursor, "height", "height ROWS");
  const int width = headerSide(cursor, "width", "width COLUMNS");
  const std::string_view map_line = cursor.require("map", "'map'");
  const std::vector<std::string_view> map_fields = splitFields(map_line);
  if (map_fields.size() != 1 || map_fields[0] != "map") {
    cursor.fail("map", "expected 'map', the line before the rows, got " + quotedExcerpt(map_line));
  }
  const Grid grid = readRows(cursor, width, height);
  const Cell start = endpoint(options.start, freeCell(grid, false), "start", grid, source);
  const Cell goal = endpoint(options.goal, freeCell(grid, true), "goal", grid, source);
  if (start == goal && !options.goal) {
    throw ParseError(source, 0, "goal",
                     "the last free cell " + cellText(goal) + ", the default goal, is the start; choose another goal");
  }
  if (start == goal) throw InvalidArgument("goal", "must differ from start " + cellText(start));
  try {
    return problemFromGrid(grid, start, goal);
  } catch (const InvalidArgument& e) {
    throw ParseError(source, 0, "map", e.problem());
  }
}

Problem readMovingAiMap(const std::string& path, const MapImportOptions& options) {
  return parseMovingAiMap(readTextFile(path, kMaxMovingAiMapBytes), path, options);
}

}  // namespace ppp
