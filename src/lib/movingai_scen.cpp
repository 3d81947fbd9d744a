#include "ppp_core/movingai_scen.hpp"

#include <charconv>
#include <filesystem>

#include "ppp_core/error.hpp"
#include "ppp_core/line_cursor.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {

namespace {

constexpr int kScenarioFields = 9;
// Longer than any route on the largest map (kMaxGridSide^2 cells, each at most sqrt(2) away from the next).
constexpr double kMaxLength = 2.0 * kMaxGridSide * kMaxGridSide;

int parseCount(const LineCursor& cursor, std::string_view text, const char* field, int max) {
  int value = -1;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size() || value < 0 || value > max) {
    cursor.fail(field, "expected an integer in [0, " + std::to_string(max) + "], got " + quotedExcerpt(text));
  }
  return value;
}

double parseLength(const LineCursor& cursor, std::string_view text) {
  double value = -1;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size() || !(value >= 0 && value <= kMaxLength)) {
    cursor.fail("optimal_length", "expected a length in [0, " + std::to_string(static_cast<long>(kMaxLength)) +
                                      "], got " + quotedExcerpt(text));
  }
  return value;
}

void requireInside(const LineCursor& cursor, Cell c, int width, int height, const char* field) {
  if (c.x >= width || c.y >= height) {
    cursor.fail(field, "cell " + cellText(c) + " is outside the " + std::to_string(width) + " x " +
                           std::to_string(height) + " map the line names");
  }
}

}  // namespace

std::vector<MovingAiScenario> parseMovingAiScenarios(const std::string& text, const std::string& source) {
  LineCursor cursor(text, source);
  const std::vector<std::string_view> header = splitFields(cursor.require("version", "'version 1'"));
  if (header.size() != 2 || header[0] != "version" || (header[1] != "1" && header[1] != "1.0")) {
    cursor.fail("version", "expected 'version 1' (MovingAI scenario file), got " +
                               quotedExcerpt(header.empty() ? std::string_view() : header[0]));
  }
  std::vector<MovingAiScenario> scenarios;
  std::string_view line;
  while (cursor.next(&line)) {
    const std::vector<std::string_view> fields = splitFields(line);
    if (fields.empty()) continue;  // blank lines, as at the end of some files
    if (fields.size() != kScenarioFields) {
      cursor.fail("scenario", "expected 9 fields (bucket, map, width, height, start x, start y, goal x, goal y, "
                              "optimal length), got " + std::to_string(fields.size()));
    }
    MovingAiScenario s;
    s.line = cursor.line();
    s.bucket = parseCount(cursor, fields[0], "bucket", 1 << 30);
    s.map = std::string(fields[1]);
    s.map_width = parseCount(cursor, fields[2], "width", kMaxGridSide);
    s.map_height = parseCount(cursor, fields[3], "height", kMaxGridSide);
    if (s.map_width == 0 || s.map_height == 0) cursor.fail("width", "a map of 0 cells");
    s.start = Cell{parseCount(cursor, fields[4], "start_x", kMaxGridSide), parseCount(cursor, fields[5], "start_y", kMaxGridSide)};
    s.goal = Cell{parseCount(cursor, fields[6], "goal_x", kMaxGridSide), parseCount(cursor, fields[7], "goal_y", kMaxGridSide)};
    requireInside(cursor, s.start, s.map_width, s.map_height, "start");
    requireInside(cursor, s.goal, s.map_width, s.map_height, "goal");
    s.optimal_length = parseLength(cursor, fields[8]);
    scenarios.push_back(std::move(s));
  }
  return scenarios;
}

std::vector<MovingAiScenario> readMovingAiScenarios(const std::string& path) {
  return parseMovingAiScenarios(readTextFile(path, kMaxScenarioFileBytes), path);
}

std::string formatMovingAiScenarios(const std::vector<MovingAiScenario>& scenarios) {
  std::string text = "version 1\n";
  for (const MovingAiScenario& s : scenarios) {
    const std::string length = formatFixed(s.optimal_length, 8);
    text += std::to_string(s.bucket) + "\t" + s.map + "\t" + std::to_string(s.map_width) + "\t" +
            std::to_string(s.map_height) + "\t" + std::to_string(s.start.x) + "\t" + std::to_string(s.start.y) +
            "\t" + std::to_string(s.goal.x) + "\t" + std::to_string(s.goal.y) + "\t" + length + "\n";
  }
  return text;
}

void writeMovingAiScenarios(const std::vector<MovingAiScenario>& scenarios, const std::string& path) {
  writeFileAtomically(path, formatMovingAiScenarios(scenarios));
}

std::string findScenarioMap(const std::string& scen_path, const std::string& map, const std::string& map_dir) {
  namespace fs = std::filesystem;
  const fs::path name = fs::path(map).filename();
  const fs::path scen_dir = fs::path(scen_path).parent_path();
  std::vector<std::string> tried = {map, ((scen_dir.empty() ? fs::path(".") : scen_dir) / name).string()};
  if (!map_dir.empty()) tried.push_back((fs::path(map_dir) / name).string());
  for (const std::string& candidate : tried) {
    std::error_code error;
    if (fs::is_regular_file(candidate, error)) return candidate;
  }
  std::string where;
  for (const std::string& candidate : tried) where += (where.empty() ? "" : ", ") + candidate;
  throw IoError(scen_path, "map '" + map + "' not found (looked at " + where +
                               (map_dir.empty() ? "; --map-dir names another place to look)" : ")"));
}

void checkScenarioOnMap(const MovingAiScenario& s, const Grid& grid, const std::string& source) {
  auto fail = [&](const char* field, const std::string& what) { throw ParseError(source, s.line, field, what); };
  if (s.map_width != grid.width() || s.map_height != grid.height()) {
    fail("width", "the line gives a " + std::to_string(s.map_width) + " x " + std::to_string(s.map_height) +
                      " map, but '" + s.map + "' is " + std::to_string(grid.width()) + " x " +
                      std::to_string(grid.height()));
  }
  for (const auto& [cell, field] : {std::pair<Cell, const char*>{s.start, "start"}, {s.goal, "goal"}}) {
    if (!grid.isFree(cell)) {
      fail(field, "cell " + cellText(cell) + " is " + (grid.contains(cell) ? "an obstacle" : "off the map") + " on '" +
                      s.map + "'");
    }
  }
  if (s.start == s.goal) fail("goal", "equals the start");
}

}  // namespace ppp
