#include "ppp_core/map_yaml.hpp"

#include <gtest/gtest.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/random_problem.hpp"

namespace ppp {
namespace {

namespace fs = std::filesystem;

void writeBytes(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
  ASSERT_TRUE(out.good()) << path;
}

std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream contents;
  contents << in.rdbuf();
  return contents.str();
}

/// `text` with the line that starts with "<key>:", and the indented lines of its block, replaced by `line`
/// (removed when `line` is empty).
std::string withLine(const std::string& text, const std::string& key, const std::string& line) {
  std::istringstream in(text);
  std::string out;
  std::string current;
  bool found = false;
  bool in_block = false;
  while (std::getline(in, current)) {
    if (current.rfind(key + ":", 0) == 0) {
      found = true;
      in_block = true;
      if (!line.empty()) out += line + "\n";
    } else if (in_block && !current.empty() && current[0] == ' ') {
      continue;
    } else {
      in_block = false;
      out += current + "\n";
    }
  }
  EXPECT_TRUE(found) << key;
  return out;
}

/// 1-based number of the line that starts with "<key>:".
int lineOfKey(const std::string& text, const std::string& key) {
  std::istringstream in(text);
  std::string current;
  for (int line = 1; std::getline(in, current); ++line) {
    if (current.rfind(key + ":", 0) == 0) return line;
  }
  ADD_FAILURE() << "no key " << key;
  return -1;
}

/// A 5x4 foreign map: 0 occupied, 254 and 255 free, 205 and 100 unknown (read as obstacles).
const int kForeignPixels[4][5] = {
    {254, 0, 0, 255, 254},
    {254, 254, 205, 254, 0},
    {0, 80, 0, 0, 254},
    {254, 254, 254, 100, 254},
};
/// The obstacle cells of kForeignPixels, '#' for an obstacle.
const char* const kForeignGrid[4] = {".##..", "..#.#", "####.", "...#."};

std::string foreignP5() {
  std::string pgm = "P5\n# a hand-made foreign map\n5 4\n# comment before maxval\n255\n";
  for (const auto& row : kForeignPixels) {
    for (int v : row) pgm.push_back(static_cast<char>(v));
  }
  return pgm;
}

const char* const kForeignYaml =
    "image: foreign.pgm\n"
    "resolution: 0.05\n"
    "origin: [-1.0, 2.5, 0.0]\n"
    "negate: 0\n"
    "occupied_thresh: 0.65\n"
    "free_thresh: 0.196\n";

class MapYamlTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("ppp_map_yaml_test_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  /// Writes the foreign PGM and `yaml` and returns the YAML path.
  std::string foreign(const std::string& yaml, const std::string& pgm = foreignP5()) {
    writeBytes(path("foreign.pgm"), pgm);
    writeBytes(path("foreign.yaml"), yaml);
    return path("foreign.yaml");
  }

  /// Reads `yaml_path` expecting a ParseError; returns it (a default one after a test failure).
  ParseError parseError(const std::string& yaml_path, const MapImportOptions& options = {}) {
    try {
      readMapYaml(yaml_path, options);
    } catch (const ParseError& e) {
      return e;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "expected a ParseError, got: " << e.what();
      return ParseError("", -1, "", "");
    }
    ADD_FAILURE() << "read without error: " << yaml_path;
    return ParseError("", -1, "", "");
  }

  /// Expects a ParseError for `yaml_path` at `file`:`line` in `field` whose message contains `text`.
  void expectParseError(const std::string& yaml_path, const std::string& file, int line, const std::string& field,
                        const std::string& text) {
    const ParseError e = parseError(yaml_path);
    EXPECT_EQ(e.file(), file) << e.what();
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what() << "\nexpected to contain: " << text;
  }

  /// A small PPP written with writeMapYaml; returns the YAML path.
  std::string writtenMap(Problem* problem = nullptr) {
    Problem p = Problem::empty(6, 4, 3);
    p.obstacles = {{Shape::VerticalBar, 2, 0, 3, 1}, {Shape::Block, 4, 1, 2, 2}};
    setMetadata(&p.metadata, "fitness", "turns");
    writeMapYaml(p, path("map.yaml"));
    if (problem != nullptr) *problem = p;
    return path("map.yaml");
  }

  fs::path dir_;
};

TEST_F(MapYamlTest, RandomProblemsRoundTripExactly) {
  Rng rng(31337);
  const char* const tricky[] = {"null", "~", "true", "1.50", "a: b # c", "'quoted' \"double\"", "[x]", "-", "0x10"};
  for (int i = 0; i < 150; ++i) {
    const int w = static_cast<int>(rng.uniformInt(2, 40));
    const int h = static_cast<int>(rng.uniformInt(2, 40));
    const int budget = static_cast<int>(rng.uniformInt(0, 15));
    Problem p = randomProblem(rng, Problem::empty(w, h, budget), static_cast<int>(rng.uniformInt(0, budget)));
    setMetadata(&p.metadata, "seed", std::to_string(i));
    setMetadata(&p.metadata, "note", tricky[i % std::size(tricky)]);
    if (i % 5 == 0) p.metadata.clear();
    MapYamlOptions options;
    options.resolution = 0.05 * (1 + i % 7);
    options.origin_x = -1.25 * (i % 3);
    options.origin_y = 0.1 * i;
    options.origin_yaw = i % 2 == 0 ? 0.0 : 0.3;
    const std::string yaml = path("random_" + std::to_string(i % 3) + ".yaml");
    writeMapYaml(p, yaml, options);
    MapYamlOptions geometry;
    const Problem back = readMapYaml(yaml, {}, &geometry);
    EXPECT_EQ(back, p) << readBytes(yaml);
    EXPECT_EQ(geometry.resolution, options.resolution);
    EXPECT_EQ(geometry.origin_x, options.origin_x);
    EXPECT_EQ(geometry.origin_y, options.origin_y);
    EXPECT_EQ(geometry.origin_yaw, options.origin_yaw);
  }
}

TEST_F(MapYamlTest, TextEntryPointsMatchTheFiles) {
  Problem p;
  const std::string yaml = writtenMap(&p);
  const MapYamlText text = formatMapYaml(p, "map.pgm");
  EXPECT_EQ(text.yaml, readBytes(yaml));
  EXPECT_EQ(text.pgm, readBytes(path("map.pgm")));
  std::string asked;
  const MapImageSource image = [&](const std::string& image_path) {
    asked = image_path;
    return text.pgm;
  };
  EXPECT_EQ(parseMapYaml(text.yaml, "maps/a.yaml", image), p);
  EXPECT_EQ(asked, "maps/map.pgm");
  try {
    parseMapYaml(text.yaml + "ppp_colour: 1\n", "maps/a.yaml", image);
    ADD_FAILURE() << "an unknown ppp_ key was accepted";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "maps/a.yaml");
    EXPECT_EQ(e.field(), "ppp_colour");
  }
}

TEST_F(MapYamlTest, WritesMapServerKeysAndPgmInGridOrder) {
  Problem p;
  const std::string yaml = writtenMap(&p);
  const YAML::Node root = YAML::LoadFile(yaml);
  EXPECT_EQ(root["image"].as<std::string>(), "map.pgm");
  EXPECT_EQ(root["resolution"].as<double>(), 1.0);
  EXPECT_EQ(root["origin"].size(), 3u);
  EXPECT_EQ(root["negate"].as<int>(), 0);
  EXPECT_EQ(root["occupied_thresh"].as<double>(), 0.65);
  EXPECT_EQ(root["free_thresh"].as<double>(), 0.196);
  EXPECT_EQ(root["ppp_obstacles"][1][0].as<std::string>(), "block");

  const std::string pgm = readBytes(path("map.pgm"));
  const std::string header = "P5\n";
  ASSERT_EQ(pgm.compare(0, header.size(), header), 0);
  const std::string dims = "\n6 4\n255\n";
  const std::size_t at = pgm.find(dims);
  ASSERT_NE(at, std::string::npos);
  const std::string pixels = pgm.substr(at + dims.size());
  ASSERT_EQ(pixels.size(), 24u);
  const Grid grid = decodeGrid(p);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 6; ++x) {
      const auto v = static_cast<unsigned char>(pixels[static_cast<std::size_t>(y * 6 + x)]);
      EXPECT_EQ(v, grid.isObstacle(Cell{x, y}) ? 0 : 254) << x << "," << y;
    }
  }
  // Row 0 of the image is the top row of the grid: the vbar at x = 2 starts there.
  EXPECT_EQ(static_cast<unsigned char>(pixels[2]), 0);
  EXPECT_EQ(static_cast<unsigned char>(pixels[3 * 6 + 2]), 254);
}

TEST_F(MapYamlTest, ForeignP5ImportsCellByCellAsHorizontalRuns) {
  MapYamlOptions geometry;
  const Problem p = readMapYaml(foreign(kForeignYaml), {}, &geometry);
  EXPECT_EQ(p.width, 5);
  EXPECT_EQ(p.height, 4);
  EXPECT_EQ(p.start, (Cell{0, 0}));
  EXPECT_EQ(p.goal, (Cell{4, 3}));
  EXPECT_EQ(geometry.resolution, 0.05);
  EXPECT_EQ(geometry.origin_x, -1.0);
  EXPECT_EQ(geometry.origin_y, 2.5);
  const Grid grid = decodeGrid(p);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 5; ++x) {
      EXPECT_EQ(grid.isObstacle(Cell{x, y}), kForeignGrid[y][x] == '#') << x << "," << y;
    }
  }
  const std::vector<Obstacle> runs = {
      {Shape::HorizontalBar, 1, 0, 2, 1}, {Shape::HorizontalBar, 2, 1, 1, 1}, {Shape::HorizontalBar, 4, 1, 1, 1},
      {Shape::HorizontalBar, 0, 2, 4, 1}, {Shape::HorizontalBar, 3, 3, 1, 1},
  };
  EXPECT_EQ(p.obstacles, runs);
  EXPECT_EQ(p.max_obstacles, 5);
  EXPECT_TRUE(p.metadata.empty());
}

TEST_F(MapYamlTest, ForeignP2WithCommentsAndSmallMaxvalImportsTheSame) {
  // maxval 15: 15 -> 255 (free), 14 -> 238 (free), 12 -> 204 (unknown), 0 (occupied).
  const std::string p2 =
      "P2\n# ASCII foreign map\n5 # width\n4\n15\n"
      "14 0 0 15 15\n"
      "15 15 12 15 0\n"
      "# a comment between rows\n"
      "0 0 0 0 14\n"
      "15 15 15 12 15\n";
  const Problem p = readMapYaml(foreign(kForeignYaml, p2));
  const Grid grid = decodeGrid(p);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 5; ++x) {
      EXPECT_EQ(grid.isObstacle(Cell{x, y}), kForeignGrid[y][x] == '#') << x << "," << y;
    }
  }
}

TEST_F(MapYamlTest, NegateInvertsTheGreyValues) {
  std::string pgm = "P5 5 4 255\n";
  for (const auto& row : kForeignPixels) {
    for (int v : row) pgm.push_back(static_cast<char>(255 - v));
  }
  const Problem p = readMapYaml(foreign(withLine(kForeignYaml, "negate", "negate: 1"), pgm));
  const Grid grid = decodeGrid(p);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 5; ++x) {
      EXPECT_EQ(grid.isObstacle(Cell{x, y}), kForeignGrid[y][x] == '#') << x << "," << y;
    }
  }
}

TEST_F(MapYamlTest, ForeignStartAndGoalComeFromTheOptions) {
  MapImportOptions options;
  options.start = Cell{0, 1};
  options.goal = Cell{3, 0};
  const Problem p = readMapYaml(foreign(kForeignYaml), options);
  EXPECT_EQ(p.start, (Cell{0, 1}));
  EXPECT_EQ(p.goal, (Cell{3, 0}));

  options.start = Cell{1, 0};
  const ParseError on_obstacle = parseError(path("foreign.yaml"), options);
  EXPECT_EQ(on_obstacle.field(), "start");
  EXPECT_EQ(on_obstacle.file(), path("foreign.pgm"));
  EXPECT_NE(std::string(on_obstacle.what()).find("(1, 0) is an obstacle pixel, value 0 (occupied)"), std::string::npos)
      << on_obstacle.what();

  options.start = Cell{0, 0};
  options.goal = Cell{3, 3};
  const ParseError unknown = parseError(path("foreign.yaml"), options);
  EXPECT_EQ(unknown.field(), "goal");
  EXPECT_NE(std::string(unknown.what()).find("value 100 (unknown"), std::string::npos) << unknown.what();

  options.goal = Cell{5, 0};
  EXPECT_THROW(readMapYaml(path("foreign.yaml"), options), InvalidArgument);
}

TEST_F(MapYamlTest, MissingFilesAreIoErrors) {
  EXPECT_THROW(readMapYaml(path("nothing.yaml")), IoError);
  writeBytes(path("foreign.yaml"), kForeignYaml);
  try {
    readMapYaml(path("foreign.yaml"));
    ADD_FAILURE() << "read without the image";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(path("foreign.pgm")), std::string::npos) << e.what();
  }
  EXPECT_THROW(writeMapYaml(Problem::empty(4, 4, 0), path("no/such/dir/map.yaml")), IoError);
}

TEST_F(MapYamlTest, BadYamlNamesFileLineAndField) {
  const std::string y = path("foreign.yaml");
  struct Case {
    std::string key;   // the line to replace
    std::string line;  // replacement ("" removes the key)
    int expected_line;
    std::string field;
    std::string text;
  };
  const Case cases[] = {
      {"image", "", 0, "image", "missing key"},
      {"image", "image: [a, b]", 1, "image", "expected a string"},
      {"image", "image: ''", 1, "image", "empty file name"},
      {"resolution", "resolution: -0.5", 2, "resolution", "expected metres per cell > 0"},
      {"resolution", "resolution: 0", 2, "resolution", "expected metres per cell > 0"},
      {"resolution", "resolution: fast", 2, "resolution", "expected a number, got 'fast'"},
      {"resolution", "resolution: .nan", 2, "resolution", "expected a finite number"},
      {"resolution", "", 0, "resolution", "missing key"},
      {"origin", "origin: [1, 2]", 3, "origin", "expected [x, y, yaw]"},
      {"origin", "origin: [1, two, 0]", 3, "origin", "expected a number, got 'two'"},
      {"negate", "negate: 2", 4, "negate", "expected 0 or 1"},
      {"occupied_thresh", "occupied_thresh: high", 5, "occupied_thresh", "expected a number, got 'high'"},
      {"occupied_thresh", "occupied_thresh: 1.5", 5, "occupied_thresh", "expected a probability in [0, 1]"},
      {"occupied_thresh", "occupied_thresh: {a: 1}", 5, "occupied_thresh", "expected a number, got a mapping"},
      {"free_thresh", "free_thresh: -0.1", 6, "free_thresh", "expected a probability in [0, 1]"},
      {"free_thresh", "free_thresh: 0.65", 6, "free_thresh", "must be below occupied_thresh 0.65"},
      {"free_thresh", "free_thresh: 0.9", 6, "free_thresh", "must be below occupied_thresh"},
      {"free_thresh", "", 0, "free_thresh", "missing key"},
      {"free_thresh", "free_thresh: 0.196\nmode: raw", 7, "mode", "only 'trinary'"},
      {"free_thresh", "free_thresh: 0.196\nresolution: 2", 7, "resolution", "duplicate key"},
      {"free_thresh", "free_thresh: 0.196\nppp_colour: red", 7, "ppp_colour", "unknown PPP key"},
      {"origin", "origin: [1, 2, 0", 4, "yaml", ""},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.line);
    foreign(withLine(kForeignYaml, c.key, c.line));
    expectParseError(y, y, c.expected_line, c.field, c.text);
  }
  foreign("- just\n- a list\n");
  expectParseError(y, y, 1, "yaml", "expected a mapping");
}

TEST_F(MapYamlTest, BadPgmNamesTheImage) {
  const std::string y = path("foreign.yaml");
  const std::string image = path("foreign.pgm");
  struct Case {
    std::string pgm;
    int expected_line;
    std::string field;
    std::string text;
  };
  const Case cases[] = {
      {"P6\n5 4\n255\n", 1, "magic", "expected a PGM image ('P5' binary or 'P2' ASCII), got 'P6'"},
      {"\x89PNG\r\n\x1a\n", 1, "magic", "got '\\x89P'"},
      {"", 1, "magic", "expected a PGM image"},
      {"P5\n1 4\n255\n", 2, "width", "the image width 1 is outside [2, 4096]"},
      {"P5\n5\n# big\n5000\n255\n", 4, "height", "the image height 5000 is outside [2, 4096]"},
      {"P5 99999999999999999999999 4 255\n", 1, "width", "outside [2, 4096]"},
      {"P5 -5 4 255\n", 1, "width", "expected the image width, got '-5'"},
      {"P5 5 4\n", 2, "maxval", "unexpected end of file"},
      {"P5 5 4 256\n", 1, "maxval", "outside [1, 255]"},
      {"P5 5 4 0\n", 1, "maxval", "outside [1, 255]"},
      {"P5 5 4 255", 1, "maxval", "expected one whitespace character"},
      {"P5 5 4 255\n" + std::string(19, '\xfe'), 0, "pixels", "needs 20 bytes of pixel data, the file holds 19"},
      {"P5 5 4 100\n" + std::string(7, '\x01') + "\x65" + std::string(12, '\x01'), 0, "pixel (2, 1)",
       "value 101 exceeds maxval 100"},
      {"P2 5 4 255\n1 2 3\n4 5 6\n", 4, "pixels", "needs 20 values, the file holds 6"},
      {"P2 5 4 255\n1 2 x 4\n", 2, "pixel (2, 0)", "expected a grey value, got 'x'"},
      {"P2 5 4 9\n1 2 10 4\n", 2, "pixel (2, 0)", "a grey value 10 is outside [0, 9]"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.pgm);
    foreign(kForeignYaml, c.pgm);
    expectParseError(y, image, c.expected_line, c.field, c.text);
  }
}

TEST_F(MapYamlTest, ImageMustAgreeWithThePppKeys) {
  Problem p;
  const std::string y = writtenMap(&p);
  const std::string image = path("map.pgm");
  const std::string original = readBytes(image);

  // One pixel flipped: the vbar cell (2, 1) made free.
  std::string flipped = original;
  flipped[flipped.size() - 24 + 1 * 6 + 2] = static_cast<char>(254);
  writeBytes(image, flipped);
  expectParseError(y, image, 0, "pixel (2, 1)", "value 254 (free) but ppp_obstacles make the cell an obstacle");

  // A free cell painted unknown.
  flipped = original;
  flipped[flipped.size() - 24 + 0 * 6 + 1] = static_cast<char>(205);
  writeBytes(image, flipped);
  expectParseError(y, image, 0, "pixel (1, 0)", "value 205 (unknown, read as an obstacle) but ppp_obstacles make");

  // A 5x4 image for a 6x4 problem.
  std::string smaller = "P5\n5 4\n255\n" + std::string(20, '\xfe');
  writeBytes(image, smaller);
  const std::string yaml_text = readBytes(y);
  expectParseError(y, y, lineOfKey(yaml_text, "ppp_size"), "ppp_size", "is 5x4 pixels but ppp_size is 6x4");
  writeBytes(image, original);
  EXPECT_EQ(readMapYaml(y), p);
}

TEST_F(MapYamlTest, BadPppKeysNameTheLine) {
  const std::string y = writtenMap();
  const std::string text = readBytes(y);
  struct Case {
    std::string key;
    std::string line;
    std::string field;
    std::string message;
    std::string line_key = "";  // the key whose line the error names, when not `key`
  };
  const Case cases[] = {
      {"ppp_size", "ppp_size: [6]", "ppp_size", "expected [WIDTH, HEIGHT]"},
      {"ppp_size", "ppp_size: [1, 4]", "ppp_size", "expected width and height in [2, 4096], got 1x4"},
      {"ppp_start", "ppp_start: [a, 0]", "ppp_start", "expected an integer, got 'a'"},
      {"ppp_start", "ppp_start: [6, 0]", "ppp_start", "cell (6, 0) is outside the 6x4 grid"},
      {"ppp_goal", "ppp_goal: [0, 0]", "ppp_goal", "must differ from ppp_start (0, 0)"},
      {"ppp_max_obstacles", "ppp_max_obstacles: 1.5", "ppp_max_obstacles", "expected an integer, got '1.5'"},
      {"ppp_max_obstacles", "ppp_max_obstacles: 1", "ppp_obstacles", "2 descriptors exceed ppp_max_obstacles 1",
       "ppp_obstacles"},
      {"ppp_max_obstacles", "ppp_max_obstacles: -2", "ppp_max_obstacles", "expected an integer in [0,"},
      {"ppp_obstacles", "ppp_obstacles: 3", "ppp_obstacles", "expected a list"},
      {"ppp_metadata", "ppp_metadata: [1, 2]", "ppp_metadata", "expected a mapping"},
      {"ppp_metadata", "ppp_metadata: {fitness: \"\"}", "ppp_metadata fitness", "empty value"},
      {"ppp_metadata", "ppp_metadata: {\"bad key\": x}", "ppp_metadata bad key", "may hold only"},
      {"ppp_metadata", "ppp_metadata: {a: 1, a: 2}", "ppp_metadata", "duplicate key 'a'"},
      {"ppp_metadata", "ppp_metadata: {a: [1]}", "ppp_metadata a", "expected a string"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.line);
    const std::string changed = withLine(text, c.key, c.line);
    writeBytes(y, changed);
    expectParseError(y, y, lineOfKey(changed, c.line_key.empty() ? c.key : c.line_key), c.field, c.message);
  }
  // A missing key: the whole file is at fault.
  writeBytes(y, withLine(text, "ppp_goal", ""));
  expectParseError(y, y, 0, "ppp_goal", "missing key");

  // Bad descriptors point at their own line.
  const int first = lineOfKey(text, "ppp_obstacles") + 1;
  const std::string obstacles_key = "ppp_obstacles:\n";
  const std::size_t at = text.find(obstacles_key) + obstacles_key.size();
  const std::size_t end = text.find("ppp_metadata:");
  const std::pair<std::string, std::string> bad_descriptors[] = {
      {"  - [star, 1, 1, 2]\n", "expected a shape"},
      {"  - [block, 1, 1, 2]\n", "expected [block, X, Y, W, H]"},
      {"  - [hbar, 1, 1]\n", "expected [hbar, X, Y, LENGTH]"},
      {"  - [vbar, 1, 9, 2]\n", "cell (1, 9) is outside the 6x4 grid"},
      {"  - [vbar, 1, 1, 0]\n", "vbar length 0 outside [1, 6]"},
      {"  - hbar\n", "expected [SHAPE, X, Y, LENGTH]"},
  };
  for (const auto& bad : bad_descriptors) {
    SCOPED_TRACE(bad.first);
    writeBytes(y, text.substr(0, at) + "  - [hbar, 0, 1, 1]\n" + bad.first + text.substr(end));
    expectParseError(y, y, first + 1, "ppp_obstacles[1]", bad.second);
  }
}

TEST_F(MapYamlTest, WriterRefusesBadInput) {
  const Problem p = Problem::empty(4, 4, 0);
  MapYamlOptions options;
  options.resolution = 0.0;
  EXPECT_THROW(writeMapYaml(p, path("a.yaml"), options), InvalidArgument);
  options.resolution = 1.0;
  options.origin_x = std::numeric_limits<double>::infinity();
  EXPECT_THROW(writeMapYaml(p, path("a.yaml"), options), InvalidArgument);
  EXPECT_THROW(writeMapYaml(p, path("a.pgm")), InvalidArgument);
  Problem bad = p;
  bad.goal = bad.start;
  EXPECT_THROW(writeMapYaml(bad, path("a.yaml")), InvalidArgument);
  EXPECT_FALSE(fs::exists(path("a.yaml")));
  EXPECT_FALSE(fs::exists(path("a.pgm")));
}

}  // namespace
}  // namespace ppp
