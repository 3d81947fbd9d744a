#include "ppp_core/ppp_file.hpp"

#include <charconv>
#include <cstdio>
#include <sstream>
#include <string_view>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/line_cursor.hpp"
#include "ppp_core/text_file.hpp"

namespace ppp {

namespace {

constexpr const char* kMagic = "ppp";
constexpr int kVersion = 1;

bool isMetadataKeyChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.' ||
         c == '-';
}

int parseInt(const LineCursor& cursor, std::string_view token, const std::string& field, const char* what) {
  int value = 0;
  const char* begin = token.data();
  const char* end = token.data() + token.size();
  auto result = std::from_chars(begin, end, value);
  if (token.empty() || result.ec != std::errc() || result.ptr != end) {
    cursor.fail(field, std::string(what) + " must be an integer, got " + quotedExcerpt(token));
  }
  return value;
}

/// Splits a "<keyword> <n values>" line, checking keyword and count.
std::vector<std::string_view> keywordLine(LineCursor& cursor, const std::string& keyword, std::size_t values,
                                          const std::string& usage) {
  std::string_view line = cursor.require(keyword, "'" + usage + "'");
  auto tokens = splitFields(line);
  if (tokens.empty() || tokens[0] != keyword) {
    cursor.fail(keyword, "expected '" + usage + "', got " + quotedExcerpt(line));
  }
  if (tokens.size() != values + 1) {
    cursor.fail(keyword,
                "expected '" + usage + "' (" + std::to_string(values) + " values), got " + quotedExcerpt(line));
  }
  return tokens;
}

void checkText(const std::string& text, const std::string& source) {
  int line = 1;
  int column = 1;
  for (unsigned char c : text) {
    if (c == '\n') {
      ++line;
      column = 1;
      continue;
    }
    if ((c < 0x20 && c != '\t' && c != '\r') || c >= 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", c);
      throw ParseError(source, line, "file",
                       "binary data (byte " + std::string(hex) + " at column " + std::to_string(column) +
                           "); expected a text .ppp file");
    }
    ++column;
  }
}

Cell parseCellLine(LineCursor& cursor, const std::string& keyword, int width, int height) {
  auto tokens = keywordLine(cursor, keyword, 2, keyword + " X Y");
  Cell c{parseInt(cursor, tokens[1], keyword, "x"), parseInt(cursor, tokens[2], keyword, "y")};
  if (c.x < 0 || c.y < 0 || c.x >= width || c.y >= height) {
    cursor.fail(keyword, "cell " + cellText(c) + " is outside the " +
                             std::to_string(width) + "x" + std::to_string(height) + " grid");
  }
  return c;
}

Obstacle parseObstacleLine(LineCursor& cursor, int index, const Problem& p) {
  const std::string field = "obstacle " + std::to_string(index);
  std::string_view line = cursor.require(field, "a descriptor such as 'hbar X Y LENGTH'");
  auto tokens = splitFields(line);
  Obstacle o;
  if (tokens.empty() || !parseShape(std::string(tokens[0]), &o.shape)) {
    cursor.fail(field, "expected a shape (hbar, vbar, diag_down, diag_up, block), got " + quotedExcerpt(line));
  }
  const bool block = o.shape == Shape::Block;
  const std::size_t expected = block ? 5 : 4;
  if (tokens.size() != expected) {
    cursor.fail(field, block ? "expected 'block X Y WIDTH HEIGHT', got " + quotedExcerpt(line)
                             : "expected '" + std::string(tokens[0]) + " X Y LENGTH', got " + quotedExcerpt(line));
  }
  o.x = parseInt(cursor, tokens[1], field, "x");
  o.y = parseInt(cursor, tokens[2], field, "y");
  o.length = parseInt(cursor, tokens[3], field, block ? "width" : "length");
  o.height = block ? parseInt(cursor, tokens[4], field, "height") : 1;
  try {
    validateObstacle(o, p.width, p.height, field);
  } catch (const InvalidArgument& e) {
    cursor.fail(field, std::string(e.what()).substr(field.size() + 2));
  }
  return o;
}

void parseGridRows(LineCursor& cursor, const Problem& p) {
  auto tokens = keywordLine(cursor, "grid", 0, "grid");
  (void)tokens;
  const Grid decoded = decodeGrid(p);
  for (int y = 0; y < p.height; ++y) {
    const std::string field = "grid row " + std::to_string(y);
    std::string_view row = cursor.require(field, std::to_string(p.height) + " grid rows");
    if (static_cast<int>(row.size()) != p.width) {
      cursor.fail(field, "expected " + std::to_string(p.width) + " cells, got " + std::to_string(row.size()));
    }
    for (int x = 0; x < p.width; ++x) {
      const Cell c{x, y};
      const char got = row[x];
      char want = decoded.isObstacle(c) ? '#' : '.';
      if (c == p.start) want = 'S';
      if (c == p.goal) want = 'G';
      if (got == want) continue;
      const std::string where = "column " + std::to_string(x) + ": ";
      if (got != '.' && got != '#' && got != 'S' && got != 'G') {
        cursor.fail(field, where + "unknown cell '" + std::string(1, got) + "'; expected '.', '#', 'S' or 'G'");
      }
      if (want == 'S' || want == 'G') {
        cursor.fail(field, where + "the " + std::string(want == 'S' ? "start" : "goal") + " cell must be '" +
                               std::string(1, want) + "' and is never an obstacle, got '" + std::string(1, got) +
                               "'");
      }
      if (got == 'S' || got == 'G') {
        cursor.fail(field, where + "'" + std::string(1, got) + "' does not match the " +
                               (got == 'S' ? "start" : "goal") + " line");
      }
      cursor.fail(field, where + "grid shows '" + std::string(1, got) + "' but the descriptors make the cell '" +
                             std::string(1, want) + "'");
    }
  }
}

void validateMetadataEntry(const std::string& key, const std::string& value) {
  if (key.empty()) throw InvalidArgument("metadata", "empty key");
  for (char c : key) {
    if (!isMetadataKeyChar(c)) throw InvalidArgument("metadata", "key '" + key + "' may hold only [A-Za-z0-9_.-]");
  }
  if (value.empty()) throw InvalidArgument("metadata " + key, "empty value");
  if (value.front() == ' ' || value.back() == ' ') {
    throw InvalidArgument("metadata " + key, "value has leading or trailing spaces");
  }
  for (unsigned char c : value) {
    if (c < 0x20 || c >= 0x7f) throw InvalidArgument("metadata " + key, "value holds a non-printable character");
  }
}

}  // namespace

std::string formatPpp(const Problem& p) {
  validateProblem(p);
  for (const auto& entry : p.metadata) validateMetadataEntry(entry.first, entry.second);
  std::ostringstream out;
  out << kMagic << ' ' << kVersion << '\n';
  out << "size " << p.width << ' ' << p.height << '\n';
  out << "start " << p.start.x << ' ' << p.start.y << '\n';
  out << "goal " << p.goal.x << ' ' << p.goal.y << '\n';
  out << "max_obstacles " << p.max_obstacles << '\n';
  out << "obstacles " << p.obstacles.size() << '\n';
  for (const Obstacle& o : p.obstacles) {
    out << shapeName(o.shape) << ' ' << o.x << ' ' << o.y << ' ' << o.length;
    if (o.shape == Shape::Block) out << ' ' << o.height;
    out << '\n';
  }
  out << "grid\n";
  const Grid grid = decodeGrid(p);
  std::string row(static_cast<std::size_t>(p.width), '.');
  for (int y = 0; y < p.height; ++y) {
    for (int x = 0; x < p.width; ++x) {
      const Cell c{x, y};
      row[x] = c == p.start ? 'S' : c == p.goal ? 'G' : grid.isObstacle(c) ? '#' : '.';
    }
    out << row << '\n';
  }
  for (const auto& entry : p.metadata) out << "meta " << entry.first << ' ' << entry.second << '\n';
  out << "end\n";
  return out.str();
}

Problem parsePpp(const std::string& text, const std::string& source) {
  if (text.empty()) throw ParseError(source, 1, "magic", "empty file; expected 'ppp 1' on the first line");
  checkText(text, source);
  LineCursor cursor(text, source);
  {
    std::string_view line = cursor.require("magic", "'ppp 1'");
    auto tokens = splitFields(line);
    if (tokens.empty() || tokens[0] != kMagic) {
      cursor.fail("magic", "expected 'ppp 1' (a .ppp file), got " + quotedExcerpt(line));
    }
    if (tokens.size() != 2 || tokens[1] != "1") {
      cursor.fail("version", "unsupported version " + quotedExcerpt(line.substr(tokens[0].size())) +
                                 "; this reader understands 'ppp 1'");
    }
  }
  Problem p;
  {
    auto tokens = keywordLine(cursor, "size", 2, "size WIDTH HEIGHT");
    p.width = parseInt(cursor, tokens[1], "size", "width");
    p.height = parseInt(cursor, tokens[2], "size", "height");
    if (p.width < kMinGridSide || p.height < kMinGridSide || p.width > kMaxGridSide || p.height > kMaxGridSide) {
      cursor.fail("size", "expected width and height in [" + std::to_string(kMinGridSide) + ", " +
                              std::to_string(kMaxGridSide) + "], got " + std::to_string(p.width) + "x" +
                              std::to_string(p.height));
    }
  }
  p.start = parseCellLine(cursor, "start", p.width, p.height);
  p.goal = parseCellLine(cursor, "goal", p.width, p.height);
  if (p.start == p.goal) cursor.fail("goal", "must differ from start");
  {
    auto tokens = keywordLine(cursor, "max_obstacles", 1, "max_obstacles N");
    p.max_obstacles = parseInt(cursor, tokens[1], "max_obstacles", "budget");
    if (p.max_obstacles < 0 || p.max_obstacles > kMaxObstacleBudget) {
      cursor.fail("max_obstacles", "expected an integer in [0, " + std::to_string(kMaxObstacleBudget) + "], got " +
                                       std::to_string(p.max_obstacles));
    }
  }
  int count = 0;
  {
    auto tokens = keywordLine(cursor, "obstacles", 1, "obstacles N");
    count = parseInt(cursor, tokens[1], "obstacles", "count");
    if (count < 0 || count > p.max_obstacles) {
      cursor.fail("obstacles", "count " + std::to_string(count) + " outside [0, max_obstacles = " +
                                   std::to_string(p.max_obstacles) + "]");
    }
  }
  for (int i = 1; i <= count; ++i) p.obstacles.push_back(parseObstacleLine(cursor, i, p));
  parseGridRows(cursor, p);
  for (;;) {
    std::string_view line = cursor.require("end", "'meta KEY VALUE' or 'end'");
    if (line == "end") break;
    if (line.substr(0, 5) != "meta ") {
      cursor.fail("meta", "expected 'meta KEY VALUE' or 'end', got " + quotedExcerpt(line));
    }
    std::string_view rest = line.substr(5);
    const std::size_t space = rest.find(' ');
    if (space == std::string_view::npos) cursor.fail("meta", "expected 'meta KEY VALUE', got " + quotedExcerpt(line));
    const std::string key(rest.substr(0, space));
    const std::string value(rest.substr(space + 1));
    try {
      validateMetadataEntry(key, value);
    } catch (const InvalidArgument& e) {
      cursor.fail("meta", e.what());
    }
    if (findMetadata(p.metadata, key) != nullptr) cursor.fail("meta", "duplicate key '" + key + "'");
    p.metadata.emplace_back(key, value);
  }
  std::string_view extra;
  while (cursor.next(&extra)) {
    if (!splitFields(extra).empty()) cursor.fail("end", "trailing data after 'end': " + quotedExcerpt(extra));
  }
  return p;
}

Problem readPppFile(const std::string& path) { return parsePpp(readTextFile(path, kMaxPppFileBytes), path); }

void writePppFile(const Problem& problem, const std::string& path) { writeFileAtomically(path, formatPpp(problem)); }

}  // namespace ppp
