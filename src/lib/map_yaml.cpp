#include "ppp_core/map_yaml.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/line_cursor.hpp"
#include "ppp_core/ppp_file.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {

namespace {

namespace fs = std::filesystem;

/// The ppp_* keys, in the order writeMapYaml() emits them.
const char* const kPppKeys[] = {"ppp_size",          "ppp_start",     "ppp_goal",
                                "ppp_max_obstacles", "ppp_obstacles", "ppp_metadata"};

// ---------------------------------------------------------------------------------------------------------
// Writing

std::string encodePgm(const Grid& grid) {
  std::string out = "P5\n# PPP Lab map: free " + std::to_string(kPgmFreeValue) + ", occupied " +
                    std::to_string(kPgmOccupiedValue) + "\n" + std::to_string(grid.width()) + " " +
                    std::to_string(grid.height()) + "\n255\n";
  out.reserve(out.size() + static_cast<std::size_t>(grid.size()));
  for (std::uint8_t cell : grid.cells()) {
    out.push_back(static_cast<char>(cell != 0 ? kPgmOccupiedValue : kPgmFreeValue));
  }
  return out;
}

std::string encodeYaml(const Problem& p, const std::string& image_name, const MapYamlOptions& options) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "image" << YAML::Value << image_name;
  out << YAML::Key << "resolution" << YAML::Value << formatShortest(options.resolution);
  out << YAML::Key << "origin" << YAML::Value << YAML::Flow << YAML::BeginSeq << formatShortest(options.origin_x)
      << formatShortest(options.origin_y) << formatShortest(options.origin_yaw) << YAML::EndSeq;
  out << YAML::Key << "negate" << YAML::Value << 0;
  out << YAML::Key << "occupied_thresh" << YAML::Value << formatShortest(kDefaultOccupiedThresh);
  out << YAML::Key << "free_thresh" << YAML::Value << formatShortest(kDefaultFreeThresh);
  out << YAML::Key << "ppp_size" << YAML::Value << YAML::Flow << YAML::BeginSeq << p.width << p.height << YAML::EndSeq;
  out << YAML::Key << "ppp_start" << YAML::Value << YAML::Flow << YAML::BeginSeq << p.start.x << p.start.y
      << YAML::EndSeq;
  out << YAML::Key << "ppp_goal" << YAML::Value << YAML::Flow << YAML::BeginSeq << p.goal.x << p.goal.y << YAML::EndSeq;
  out << YAML::Key << "ppp_max_obstacles" << YAML::Value << p.max_obstacles;
  out << YAML::Key << "ppp_obstacles" << YAML::Value;
  if (p.obstacles.empty()) out << YAML::Flow;
  out << YAML::BeginSeq;
  for (const Obstacle& o : p.obstacles) {
    out << YAML::Flow << YAML::BeginSeq << shapeName(o.shape) << o.x << o.y << o.length;
    if (o.shape == Shape::Block) out << o.height;
    out << YAML::EndSeq;
  }
  out << YAML::EndSeq;
  out << YAML::Key << "ppp_metadata" << YAML::Value;
  if (p.metadata.empty()) out << YAML::Flow;
  out << YAML::BeginMap;
  for (const auto& entry : p.metadata) {
    // Quoted so that values such as "null", "~" or "true" come back as the same strings.
    out << YAML::Key << entry.first << YAML::Value << YAML::DoubleQuoted << entry.second;
  }
  out << YAML::EndMap;
  out << YAML::EndMap;
  if (!out.good()) throw InvalidArgument("map yaml", "cannot emit YAML: " + out.GetLastError());
  return std::string(out.c_str()) + "\n";
}

// ---------------------------------------------------------------------------------------------------------
// Reading the YAML

/// Typed access to YAML nodes whose failures are ParseErrors pointing at the node's line.
class YamlReader {
 public:
  explicit YamlReader(const std::string& file) : file_(file) {}

  const std::string& file() const { return file_; }

  /// 1-based line of a node, 0 when it has none (a missing key).
  static int lineOf(const YAML::Node& node) {
    const YAML::Mark mark = node.Mark();
    return mark.is_null() ? 0 : mark.line + 1;
  }

  [[noreturn]] void fail(const YAML::Node& node, const std::string& field, const std::string& what) const {
    throw ParseError(file_, lineOf(node), field, what);
  }

  /// Fails at the line of `key` itself in `map` (a block list's own mark is its first item).
  [[noreturn]] void failAtKey(const YAML::Node& map, const std::string& key, const std::string& what) const {
    for (const auto& entry : map) {
      if (entry.first.IsScalar() && entry.first.Scalar() == key) fail(entry.first, key, what);
    }
    throw ParseError(file_, 0, key, what);
  }

  /// The value of `key` in the root map; a missing key is an error of the file as a whole (line 0).
  YAML::Node require(const YAML::Node& map, const std::string& key, const std::string& expected) const {
    const YAML::Node node = map[key];
    if (!node) throw ParseError(file_, 0, key, "missing key; expected " + expected);
    return node;
  }

  double number(const YAML::Node& node, const std::string& field) const {
    double value = 0.0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value)) {
      fail(node, field, "expected a number, got " + describe(node));
    }
    if (!std::isfinite(value)) fail(node, field, "expected a finite number, got " + describe(node));
    return value;
  }

  int integer(const YAML::Node& node, const std::string& field) const {
    int value = 0;
    if (!node.IsScalar() || !YAML::convert<int>::decode(node, value)) {
      fail(node, field, "expected an integer, got " + describe(node));
    }
    return value;
  }

  std::string string(const YAML::Node& node, const std::string& field) const {
    if (!node.IsScalar()) fail(node, field, "expected a string, got " + describe(node));
    return node.Scalar();
  }

  /// A sequence of exactly `count` elements.
  void requireSequence(const YAML::Node& node, const std::string& field, std::size_t count,
                       const std::string& usage) const {
    if (!node.IsSequence() || node.size() != count) fail(node, field, "expected " + usage + ", got " + describe(node));
  }

  /// A short rendering of a node for error messages.
  static std::string describe(const YAML::Node& node) {
    switch (node.Type()) {
      case YAML::NodeType::Null:
        return "null";
      case YAML::NodeType::Scalar: {
        constexpr std::size_t kShown = 40;
        std::string shown = node.Scalar().substr(0, kShown);
        if (node.Scalar().size() > kShown) shown += "...";
        return "'" + shown + "'";
      }
      case YAML::NodeType::Sequence:
        return "a list of " + std::to_string(node.size());
      case YAML::NodeType::Map:
        return "a mapping";
      default:
        return "nothing";
    }
  }

 private:
  const std::string& file_;
};

/// What the map_server keys say about reading the image.
struct MapHeader {
  std::string image_path;  ///< Resolved against the YAML's directory.
  MapYamlOptions geometry;
  bool negate = false;
  double occupied_thresh = kDefaultOccupiedThresh;
  double free_thresh = kDefaultFreeThresh;
};

MapHeader readHeader(const YamlReader& r, const YAML::Node& root, const std::string& yaml_path) {
  MapHeader h;
  {
    const YAML::Node image = r.require(root, "image", "the PGM file name");
    const std::string name = r.string(image, "image");
    if (name.empty()) r.fail(image, "image", "empty file name");
    const fs::path path(name);
    h.image_path = path.is_absolute() ? name : (fs::path(yaml_path).parent_path() / path).string();
  }
  {
    const YAML::Node node = r.require(root, "resolution", "metres per cell");
    h.geometry.resolution = r.number(node, "resolution");
    if (h.geometry.resolution <= 0.0) {
      r.fail(node, "resolution", "expected metres per cell > 0, got " + YamlReader::describe(node));
    }
  }
  {
    const YAML::Node node = r.require(root, "origin", "[x, y, yaw]");
    r.requireSequence(node, "origin", 3, "[x, y, yaw]");
    h.geometry.origin_x = r.number(node[0], "origin");
    h.geometry.origin_y = r.number(node[1], "origin");
    h.geometry.origin_yaw = r.number(node[2], "origin");
  }
  {
    const YAML::Node node = r.require(root, "negate", "0 or 1");
    int negate = 0;
    bool flag = false;
    if (node.IsScalar() && YAML::convert<int>::decode(node, negate) && (negate == 0 || negate == 1)) {
      h.negate = negate == 1;
    } else if (node.IsScalar() && YAML::convert<bool>::decode(node, flag)) {
      h.negate = flag;
    } else {
      r.fail(node, "negate", "expected 0 or 1, got " + YamlReader::describe(node));
    }
  }
  const YAML::Node occupied = r.require(root, "occupied_thresh", "a probability in [0, 1]");
  const YAML::Node free = r.require(root, "free_thresh", "a probability in [0, 1]");
  h.occupied_thresh = r.number(occupied, "occupied_thresh");
  h.free_thresh = r.number(free, "free_thresh");
  if (h.occupied_thresh < 0.0 || h.occupied_thresh > 1.0) {
    r.fail(occupied, "occupied_thresh", "expected a probability in [0, 1], got " + YamlReader::describe(occupied));
  }
  if (h.free_thresh < 0.0 || h.free_thresh > 1.0) {
    r.fail(free, "free_thresh", "expected a probability in [0, 1], got " + YamlReader::describe(free));
  }
  if (h.free_thresh >= h.occupied_thresh) {
    r.fail(free, "free_thresh",
           "must be below occupied_thresh " + formatShortest(h.occupied_thresh) + ", got " +
               formatShortest(h.free_thresh));
  }
  if (const YAML::Node mode = root["mode"]) {
    const std::string value = r.string(mode, "mode");
    if (value != "trinary" && value != "scale") {
      r.fail(mode, "mode", "only 'trinary' (or 'scale', read the same way) is supported, got '" + value + "'");
    }
  }
  return h;
}

Cell readCell(const YamlReader& r, const YAML::Node& root, const std::string& key, int width, int height) {
  const YAML::Node node = r.require(root, key, "[X, Y]");
  r.requireSequence(node, key, 2, "[X, Y]");
  const Cell c{r.integer(node[0], key), r.integer(node[1], key)};
  if (c.x < 0 || c.y < 0 || c.x >= width || c.y >= height) {
    r.fail(node, key,
           "cell " + cellText(c) + " is outside the " + std::to_string(width) + "x" + std::to_string(height) + " grid");
  }
  return c;
}

Obstacle readObstacle(const YamlReader& r, const YAML::Node& node, const std::string& field, int width, int height) {
  if (!node.IsSequence() || node.size() == 0) {
    r.fail(node, field, "expected [SHAPE, X, Y, LENGTH] or [block, X, Y, W, H], got " + YamlReader::describe(node));
  }
  Obstacle o;
  const std::string shape = r.string(node[0], field);
  if (!parseShape(shape, &o.shape)) {
    r.fail(node, field, "expected a shape (hbar, vbar, diag_down, diag_up, block), got '" + shape + "'");
  }
  const bool block = o.shape == Shape::Block;
  if (node.size() != (block ? 5u : 4u)) {
    r.fail(node, field,
           block ? "expected [block, X, Y, W, H], got " + YamlReader::describe(node)
                 : "expected [" + shape + ", X, Y, LENGTH], got " + YamlReader::describe(node));
  }
  o.x = r.integer(node[1], field);
  o.y = r.integer(node[2], field);
  o.length = r.integer(node[3], field);
  o.height = block ? r.integer(node[4], field) : 1;
  try {
    validateObstacle(o, width, height, field);
  } catch (const InvalidArgument& e) {
    r.fail(node, field, e.problem());
  }
  return o;
}

/// Rebuilds the problem from the ppp_* keys (everything but the image).
Problem readPppKeys(const YamlReader& r, const YAML::Node& root) {
  Problem p;
  {
    const YAML::Node node = r.require(root, "ppp_size", "[WIDTH, HEIGHT]");
    r.requireSequence(node, "ppp_size", 2, "[WIDTH, HEIGHT]");
    p.width = r.integer(node[0], "ppp_size");
    p.height = r.integer(node[1], "ppp_size");
    try {
      validateGridSize(p.width, p.height, "ppp_size");
    } catch (const InvalidArgument& e) {
      r.fail(node, "ppp_size", e.problem());
    }
  }
  p.start = readCell(r, root, "ppp_start", p.width, p.height);
  p.goal = readCell(r, root, "ppp_goal", p.width, p.height);
  if (p.start == p.goal) r.fail(root["ppp_goal"], "ppp_goal", "must differ from ppp_start " + cellText(p.start));
  {
    const YAML::Node node = r.require(root, "ppp_max_obstacles", "the obstacle budget");
    p.max_obstacles = r.integer(node, "ppp_max_obstacles");
    if (p.max_obstacles < 0 || p.max_obstacles > kMaxObstacleBudget) {
      r.fail(node, "ppp_max_obstacles",
             "expected an integer in [0, " + std::to_string(kMaxObstacleBudget) + "], got " +
                 std::to_string(p.max_obstacles));
    }
  }
  {
    const YAML::Node node = r.require(root, "ppp_obstacles", "a list of descriptors");
    if (!node.IsSequence()) r.failAtKey(root, "ppp_obstacles", "expected a list, got " + YamlReader::describe(node));
    if (node.size() > static_cast<std::size_t>(p.max_obstacles)) {
      r.failAtKey(
          root, "ppp_obstacles",
          std::to_string(node.size()) + " descriptors exceed ppp_max_obstacles " + std::to_string(p.max_obstacles));
    }
    std::size_t i = 0;
    for (const YAML::Node& entry : node) {
      p.obstacles.push_back(readObstacle(r, entry, "ppp_obstacles[" + std::to_string(i++) + "]", p.width, p.height));
    }
  }
  if (const YAML::Node node = root["ppp_metadata"]) {
    if (!node.IsMap()) r.failAtKey(root, "ppp_metadata", "expected a mapping, got " + YamlReader::describe(node));
    for (const auto& entry : node) {
      const std::string key = r.string(entry.first, "ppp_metadata");
      const std::string field = "ppp_metadata " + key;
      const std::string value = r.string(entry.second, field);
      if (findMetadata(p.metadata, key) != nullptr) r.fail(entry.first, "ppp_metadata", "duplicate key '" + key + "'");
      // The .ppp writer holds the rules for keys and values; a problem that cannot be saved is rejected here.
      Problem probe = Problem::empty(kMinGridSide, kMinGridSide, 0);
      probe.metadata.emplace_back(key, value);
      try {
        formatPpp(probe);
      } catch (const InvalidArgument& e) {
        r.fail(entry.first, field, e.problem());
      }
      p.metadata.emplace_back(key, value);
    }
  }
  return p;
}

// ---------------------------------------------------------------------------------------------------------
// Reading the PGM

struct Pgm {
  int width = 0;
  int height = 0;
  int maxval = 255;
  std::vector<std::uint8_t> values;  ///< Row-major, row 0 at the top, as stored.
};

/// Walks a PGM file token by token, counting lines for error messages.
class PgmReader {
 public:
  PgmReader(const std::string& data, const std::string& file) : data_(data), file_(file) {}

  Pgm read() {
    if (data_.size() < 2 || data_[0] != 'P' || (data_[1] != '5' && data_[1] != '2')) {
      const std::string got = data_.substr(0, 2);
      fail(1, "magic", "expected a PGM image ('P5' binary or 'P2' ASCII), got " + quotedExcerpt(got));
    }
    const bool binary = data_[1] == '5';
    pos_ = 2;
    if (pos_ < data_.size() && !isSpace(data_[pos_]) && data_[pos_] != '#') {
      fail(1, "magic", "expected whitespace after '" + data_.substr(0, 2) + "'");
    }
    Pgm pgm;
    pgm.width = static_cast<int>(readNumber("width", "the image width", kMinGridSide, kMaxGridSide));
    pgm.height = static_cast<int>(readNumber("height", "the image height", kMinGridSide, kMaxGridSide));
    pgm.maxval = static_cast<int>(readNumber("maxval", "the maximum grey value", 1, 255));
    const std::size_t count = static_cast<std::size_t>(pgm.width) * static_cast<std::size_t>(pgm.height);
    if (binary) {
      if (pos_ >= data_.size() || !isSpace(data_[pos_])) {
        fail(line_, "maxval", "expected one whitespace character between maxval and the pixel data");
      }
      ++pos_;
      const std::size_t available = data_.size() - pos_;
      if (available < count) {
        fail(0, "pixels",
             "image truncated: " + std::to_string(pgm.width) + "x" + std::to_string(pgm.height) + " needs " +
                 std::to_string(count) + " bytes of pixel data, the file holds " + std::to_string(available));
      }
      pgm.values.assign(data_.begin() + static_cast<std::ptrdiff_t>(pos_),
                        data_.begin() + static_cast<std::ptrdiff_t>(pos_ + count));
      for (std::size_t i = 0; i < count; ++i) {
        if (pgm.values[i] > pgm.maxval) {
          fail(0, pixelField(pgm, i),
               "value " + std::to_string(pgm.values[i]) + " exceeds maxval " + std::to_string(pgm.maxval));
        }
      }
    } else {
      pgm.values.resize(count);
      for (std::size_t i = 0; i < count; ++i) {
        skipSpaceAndComments();
        if (pos_ >= data_.size()) {
          fail(line_, "pixels",
               "image truncated: " + std::to_string(pgm.width) + "x" + std::to_string(pgm.height) + " needs " +
                   std::to_string(count) + " values, the file holds " + std::to_string(i));
        }
        pgm.values[i] = static_cast<std::uint8_t>(readNumber(pixelField(pgm, i), "a grey value", 0, pgm.maxval));
      }
    }
    return pgm;
  }

 private:
  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }
  static bool isDigit(char c) { return c >= '0' && c <= '9'; }

  static std::string pixelField(const Pgm& pgm, std::size_t index) {
    return "pixel (" + std::to_string(index % static_cast<std::size_t>(pgm.width)) + ", " +
           std::to_string(index / static_cast<std::size_t>(pgm.width)) + ")";
  }

  void skipSpaceAndComments() {
    while (pos_ < data_.size()) {
      const char c = data_[pos_];
      if (c == '#') {
        while (pos_ < data_.size() && data_[pos_] != '\n') ++pos_;
      } else if (isSpace(c)) {
        if (c == '\n') ++line_;
        ++pos_;
      } else {
        return;
      }
    }
  }

  /// The next decimal number, which must lie in [lo, hi].
  long long readNumber(const std::string& field, const std::string& what, long long lo, long long hi) {
    skipSpaceAndComments();
    if (pos_ >= data_.size()) fail(line_, field, "unexpected end of file; expected " + what);
    const std::size_t start = pos_;
    while (pos_ < data_.size() && isDigit(data_[pos_])) ++pos_;
    if (pos_ == start || (pos_ < data_.size() && !isSpace(data_[pos_]) && data_[pos_] != '#')) {
      std::size_t end = start;
      while (end < data_.size() && end - start < 20 && !isSpace(data_[end])) ++end;
      fail(line_, field,
           "expected " + what + ", got " + quotedExcerpt(data_.substr(start, std::max(end, start + 1) - start)));
    }
    long long value = 0;
    const auto result = std::from_chars(data_.data() + start, data_.data() + pos_, value);
    if (result.ec != std::errc() || value < lo || value > hi) {
      fail(line_, field,
           what + " " + data_.substr(start, std::min<std::size_t>(pos_ - start, 20)) + " is outside [" +
               std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
    return value;
  }

  [[noreturn]] void fail(int line, const std::string& field, const std::string& what) const {
    throw ParseError(file_, line, field, what);
  }

  const std::string& data_;
  const std::string& file_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

enum class PixelClass { Free, Occupied, Unknown };

/// map_server's trinary classification of one grey value.
PixelClass classify(int value, const Pgm& pgm, const MapHeader& h) {
  const int v = value * 255 / pgm.maxval;
  const double p = h.negate ? v / 255.0 : (255 - v) / 255.0;
  if (p > h.occupied_thresh) return PixelClass::Occupied;
  if (p < h.free_thresh) return PixelClass::Free;
  return PixelClass::Unknown;
}

std::string pixelText(int value, PixelClass c) {
  return "value " + std::to_string(value) + " (" +
         (c == PixelClass::Free       ? "free"
          : c == PixelClass::Occupied ? "occupied"
                                      : "unknown, read as an obstacle") +
         ")";
}

/// Checks an optional start or goal of a foreign map against the image.
Cell importCell(const std::optional<Cell>& option, Cell fallback, const char* name, const Pgm& pgm,
                const MapHeader& h) {
  const Cell c = option.value_or(fallback);
  if (c.x < 0 || c.y < 0 || c.x >= pgm.width || c.y >= pgm.height) {
    throw InvalidArgument(name, "cell " + cellText(c) + " is outside the " + std::to_string(pgm.width) + "x" +
                                    std::to_string(pgm.height) + " map image " + h.image_path);
  }
  const int value = pgm.values[static_cast<std::size_t>(c.y) * pgm.width + c.x];
  const PixelClass pixel = classify(value, pgm, h);
  if (pixel != PixelClass::Free) {
    throw ParseError(h.image_path, 0, name,
                     std::string("the ") + name + " cell " + cellText(c) + " is an obstacle pixel, " +
                         pixelText(value, pixel) + "; choose a free cell");
  }
  return c;
}

/// A foreign map: one hbar per horizontal run of obstacle pixels.
Problem importForeign(const Pgm& pgm, const MapHeader& h, const MapImportOptions& options) {
  const Cell start = importCell(options.start, Cell{0, 0}, "start", pgm, h);
  const Cell goal = importCell(options.goal, Cell{pgm.width - 1, pgm.height - 1}, "goal", pgm, h);
  if (start == goal) throw InvalidArgument("goal", "must differ from start " + cellText(start));
  Grid grid(pgm.width, pgm.height);
  for (int i = 0; i < grid.size(); ++i) {
    grid.setObstacle(grid.cellAt(i), classify(pgm.values[static_cast<std::size_t>(i)], pgm, h) != PixelClass::Free);
  }
  try {
    return problemFromGrid(grid, start, goal);
  } catch (const InvalidArgument& e) {
    throw ParseError(h.image_path, 0, "pixels", e.problem());
  }
}

/// A problem read from ppp_* keys must paint exactly the image.
void checkAgainstImage(const Problem& p, const Pgm& pgm, const MapHeader& h, const YamlReader& r,
                       const YAML::Node& root) {
  if (pgm.width != p.width || pgm.height != p.height) {
    r.failAtKey(root, "ppp_size",
                "the image " + h.image_path + " is " + std::to_string(pgm.width) + "x" + std::to_string(pgm.height) +
                    " pixels but ppp_size is " + std::to_string(p.width) + "x" + std::to_string(p.height));
  }
  const Grid grid = decodeGrid(p);
  for (int y = 0; y < p.height; ++y) {
    for (int x = 0; x < p.width; ++x) {
      const Cell c{x, y};
      const int value = pgm.values[static_cast<std::size_t>(grid.index(c))];
      const PixelClass pixel = classify(value, pgm, h);
      const bool image_obstacle = pixel != PixelClass::Free;
      if (image_obstacle == grid.isObstacle(c)) continue;
      throw ParseError(h.image_path, 0, "pixel " + cellText(c),
                       pixelText(value, pixel) + " but ppp_obstacles make the cell " +
                           (grid.isObstacle(c) ? "an obstacle" : "free"));
    }
  }
}

}  // namespace

void MapYamlOptions::validate() const {
  if (!std::isfinite(resolution) || resolution <= 0.0) {
    throw InvalidArgument("resolution", "expected metres per cell > 0, got " + formatShortest(resolution));
  }
  if (!std::isfinite(origin_x)) throw InvalidArgument("origin_x", "expected a finite number");
  if (!std::isfinite(origin_y)) throw InvalidArgument("origin_y", "expected a finite number");
  if (!std::isfinite(origin_yaw)) throw InvalidArgument("origin_yaw", "expected a finite number");
}

MapYamlText formatMapYaml(const Problem& problem, const std::string& image_name, const MapYamlOptions& options) {
  options.validate();
  formatPpp(problem);  // The .ppp rules (problem and metadata) decide what can be saved.
  return MapYamlText{encodeYaml(problem, image_name, options), encodePgm(decodeGrid(problem))};
}

void writeMapYaml(const Problem& problem, const std::string& yaml_path, const MapYamlOptions& options) {
  fs::path image_path(yaml_path);
  const bool names_pgm = image_path.extension() == ".pgm";
  image_path.replace_extension(".pgm");
  const MapYamlText text = formatMapYaml(problem, image_path.filename().string(), options);
  if (names_pgm) throw InvalidArgument("yaml_path", yaml_path + " ends in .pgm; the image would overwrite the YAML");
  if (fs::path(yaml_path).filename().empty()) throw InvalidArgument("yaml_path", "'" + yaml_path + "' names no file");
  writeFileAtomically(image_path.string(), text.pgm);
  writeFileAtomically(yaml_path, text.yaml);
}

Problem readMapYaml(const std::string& yaml_path, const MapImportOptions& options, MapYamlOptions* geometry) {
  return parseMapYaml(
      readTextFile(yaml_path, kMaxMapYamlBytes), yaml_path,
      [](const std::string& image_path) { return readTextFile(image_path, kMaxPgmBytes); }, options, geometry);
}

Problem parseMapYaml(const std::string& text, const std::string& yaml_path, const MapImageSource& image,
                     const MapImportOptions& options, MapYamlOptions* geometry) {
  const YamlReader r(yaml_path);
  try {
    YAML::Node loaded;
    try {
      loaded = YAML::Load(text);
    } catch (const YAML::ParserException& e) {
      throw ParseError(yaml_path, e.mark.is_null() ? 0 : e.mark.line + 1, "yaml", e.msg);
    }
    const YAML::Node root = loaded;
    if (!root.IsMap()) {
      throw ParseError(
          yaml_path, YamlReader::lineOf(root), "yaml",
          "expected a mapping of map_server keys (image, resolution, origin, ...), got " + YamlReader::describe(root));
    }
    bool has_ppp_keys = false;
    std::set<std::string> seen;
    for (const auto& entry : root) {
      const std::string key = r.string(entry.first, "yaml");
      if (!seen.insert(key).second) r.fail(entry.first, key, "duplicate key");
      if (key.compare(0, 4, "ppp_") != 0) continue;
      has_ppp_keys = true;
      bool known = false;
      for (const char* k : kPppKeys) known = known || key == k;
      if (!known) {
        r.fail(entry.first, key,
               "unknown PPP key; expected ppp_size, ppp_start, ppp_goal, ppp_max_obstacles, "
               "ppp_obstacles or ppp_metadata");
      }
    }
    const MapHeader header = readHeader(r, root, yaml_path);
    Problem problem;
    if (has_ppp_keys) problem = readPppKeys(r, root);
    const Pgm pgm = PgmReader(image(header.image_path), header.image_path).read();
    if (has_ppp_keys) {
      checkAgainstImage(problem, pgm, header, r, root);
    } else {
      problem = importForeign(pgm, header, options);
    }
    if (geometry != nullptr) *geometry = header.geometry;
    return problem;
  } catch (const YAML::Exception& e) {
    throw ParseError(yaml_path, e.mark.is_null() ? 0 : e.mark.line + 1, "yaml", e.msg);
  }
}

}  // namespace ppp
