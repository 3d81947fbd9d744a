#include "ppp_core/movingai_map.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/problem_io.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/reachability.hpp"

namespace ppp {
namespace {

namespace fs = std::filesystem;

/// A 5x3 map holding every terrain character: '.', 'G', 'S' free; '@', 'O', 'T', 'W' obstacles.
const char* const kEveryTerrain =
    "type octile\n"
    "height 3\n"
    "width 5\n"
    "map\n"
    "@.GO.\n"
    "TS@W.\n"
    "..W.T\n";
/// kEveryTerrain decoded by hand, '#' for an obstacle.
const char* const kEveryTerrainGrid[3] = {"#..#.", "#.##.", "..#.#"};

/// `text` with "\r\n" line ends.
std::string withCrLf(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\n') out.push_back('\r');
    out.push_back(c);
  }
  return out;
}

/// Expects the decoded grid of `p` to be `rows` ('#' obstacle, anything else free), cell by cell.
void expectGrid(const Problem& p, const std::vector<std::string>& rows) {
  ASSERT_EQ(p.height, static_cast<int>(rows.size()));
  ASSERT_EQ(p.width, static_cast<int>(rows[0].size()));
  const Grid grid = decodeGrid(p);
  for (int y = 0; y < p.height; ++y) {
    for (int x = 0; x < p.width; ++x) {
      EXPECT_EQ(grid.isObstacle(Cell{x, y}), rows[y][x] == '#') << "cell (" << x << ", " << y << ")";
    }
  }
}

/// The ParseError parsing `text` as `source` throws (a default one after a test failure).
ParseError parseError(const std::string& text, const std::string& source = "maze.map",
                      const MapImportOptions& options = {}) {
  try {
    parseMovingAiMap(text, source, options);
  } catch (const ParseError& e) {
    return e;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected a ParseError, got: " << e.what();
    return ParseError("", -1, "", "");
  }
  ADD_FAILURE() << "parsed without error:\n" << text;
  return ParseError("", -1, "", "");
}

TEST(MovingAiMapTest, EveryTerrainCharacterDecodesCellByCell) {
  const Problem p = parseMovingAiMap(kEveryTerrain, "every.map");
  EXPECT_EQ(p.width, 5);
  EXPECT_EQ(p.height, 3);
  expectGrid(p, {kEveryTerrainGrid[0], kEveryTerrainGrid[1], kEveryTerrainGrid[2]});
  // The first free cell in row-major order is (1, 0), the last (3, 2).
  EXPECT_EQ(p.start, (Cell{1, 0}));
  EXPECT_EQ(p.goal, (Cell{3, 2}));
  // One hbar per horizontal run of obstacles: (0,0), (3,0); (0,1), (2,1)-(3,1); (2,2), (4,2).
  const std::vector<Obstacle> runs = {
      {Shape::HorizontalBar, 0, 0, 1, 1}, {Shape::HorizontalBar, 3, 0, 1, 1}, {Shape::HorizontalBar, 0, 1, 1, 1},
      {Shape::HorizontalBar, 2, 1, 2, 1}, {Shape::HorizontalBar, 2, 2, 1, 1}, {Shape::HorizontalBar, 4, 2, 1, 1},
  };
  EXPECT_EQ(p.obstacles, runs);
  EXPECT_EQ(p.max_obstacles, 6);
  EXPECT_TRUE(p.metadata.empty());
}

TEST(MovingAiMapTest, LineEndsAndTrailingBlankLinesDoNotMatter) {
  const Problem p = parseMovingAiMap(kEveryTerrain, "every.map");
  EXPECT_EQ(parseMovingAiMap(withCrLf(kEveryTerrain), "crlf.map"), p);
  std::string unterminated = kEveryTerrain;
  unterminated.pop_back();
  EXPECT_EQ(parseMovingAiMap(unterminated, "unterminated.map"), p);
  EXPECT_EQ(parseMovingAiMap(std::string(kEveryTerrain) + "\n  \n\r\n", "blank.map"), p);
  EXPECT_EQ(parseMovingAiMap("type  octile \nheight\t3\nwidth 5\nmap \n@.GO.\nTS@W.\n..W.T\n", "spaces.map"), p);
}

TEST(MovingAiMapTest, StartAndGoalComeFromTheOptions) {
  MapImportOptions options;
  options.start = Cell{4, 1};
  options.goal = Cell{0, 2};
  Problem p = parseMovingAiMap(kEveryTerrain, "every.map", options);
  EXPECT_EQ(p.start, (Cell{4, 1}));
  EXPECT_EQ(p.goal, (Cell{0, 2}));
  expectGrid(p, {kEveryTerrainGrid[0], kEveryTerrainGrid[1], kEveryTerrainGrid[2]});

  options.goal.reset();  // one option given: the other keeps its default
  p = parseMovingAiMap(kEveryTerrain, "every.map", options);
  EXPECT_EQ(p.start, (Cell{4, 1}));
  EXPECT_EQ(p.goal, (Cell{3, 2}));
}

TEST(MovingAiMapTest, StartOrGoalOnAnObstacleOrOffTheMapIsRefused) {
  MapImportOptions options;
  options.start = Cell{3, 1};  // 'W', on the map's second row: line 6
  ParseError e = parseError(kEveryTerrain, "every.map", options);
  EXPECT_EQ(e.file(), "every.map");
  EXPECT_EQ(e.line(), 6);
  EXPECT_EQ(e.field(), "start");
  EXPECT_NE(std::string(e.what()).find("(3, 1) is an obstacle"), std::string::npos) << e.what();

  options.start.reset();
  options.goal = Cell{4, 2};  // 'T', third row: line 7
  e = parseError(kEveryTerrain, "every.map", options);
  EXPECT_EQ(e.line(), 7);
  EXPECT_EQ(e.field(), "goal");

  options.goal = Cell{5, 0};
  try {
    parseMovingAiMap(kEveryTerrain, "every.map", options);
    ADD_FAILURE() << "a goal off the map was accepted";
  } catch (const InvalidArgument& error) {
    EXPECT_EQ(error.name(), "goal");
    EXPECT_NE(error.problem().find("outside the 5x3 map every.map"), std::string::npos) << error.what();
  }
  options.goal = Cell{1, 0};  // the default start
  EXPECT_THROW(parseMovingAiMap(kEveryTerrain, "every.map", options), InvalidArgument);
}

TEST(MovingAiMapTest, MapsWithTooFewFreeCellsAreRefused) {
  ParseError e = parseError("type octile\nheight 2\nwidth 2\nmap\n@T\nOW\n");
  EXPECT_EQ(e.line(), 0);
  EXPECT_EQ(e.field(), "start");
  EXPECT_NE(std::string(e.what()).find("no free cell"), std::string::npos) << e.what();

  e = parseError("type octile\nheight 2\nwidth 2\nmap\n@T\nOG\n");
  EXPECT_EQ(e.line(), 0);
  EXPECT_EQ(e.field(), "goal");
  EXPECT_NE(std::string(e.what()).find("the last free cell (1, 1), the default goal, is the start"), std::string::npos)
      << e.what();
}

TEST(MovingAiMapTest, AnUnreachableGoalIsReadAsItIs) {
  const Problem p = parseMovingAiMap("type octile\nheight 2\nwidth 3\nmap\n.@.\n.T.\n", "walled.map");
  EXPECT_EQ(p.start, (Cell{0, 0}));
  EXPECT_EQ(p.goal, (Cell{2, 1}));
  expectGrid(p, {".#.", ".#."});
  EXPECT_FALSE(isReachable(decodeGrid(p), p.start, p.goal));
}

TEST(MovingAiMapTest, WriterDrawsFreeCellsAsDotsAndObstaclesAsAts) {
  Problem p = Problem::empty(4, 3, 2);
  // A vbar down column 1 over rows 0-1, an hbar over (2, 2)-(3, 2) whose (3, 2) is the protected goal.
  p.obstacles = {{Shape::VerticalBar, 1, 0, 2, 1}, {Shape::HorizontalBar, 2, 2, 2, 1}};
  setMetadata(&p.metadata, "fitness", "turns");
  EXPECT_EQ(formatMovingAiMap(p),
            "type octile\n"
            "height 3\n"
            "width 4\n"
            "map\n"
            ".@..\n"
            ".@..\n"
            "..@.\n");
  Problem bad = p;
  bad.goal = bad.start;
  EXPECT_THROW(formatMovingAiMap(bad), InvalidArgument);
}

TEST(MovingAiMapTest, WriteThenReadGivesTheSameGridStartAndGoal) {
  Rng rng(4242);
  for (int i = 0; i < 100; ++i) {
    const int w = static_cast<int>(rng.uniformInt(2, 30));
    const int h = static_cast<int>(rng.uniformInt(2, 30));
    Problem shape = Problem::empty(w, h, 12);
    shape.start = Cell{static_cast<int>(rng.uniformInt(0, w - 1)), 0};
    shape.goal = Cell{static_cast<int>(rng.uniformInt(0, w - 1)), h - 1};
    const Problem p = randomProblem(rng, shape, static_cast<int>(rng.uniformInt(0, 12)));
    MapImportOptions options;
    options.start = p.start;
    options.goal = p.goal;
    const std::string text = formatMovingAiMap(p);
    const Problem back = parseMovingAiMap(text, "random.map", options);
    EXPECT_EQ(decodeGrid(back), decodeGrid(p)) << text;
    EXPECT_EQ(back.start, p.start);
    EXPECT_EQ(back.goal, p.goal);
    // The rows alone decide a map: writing what was read gives the same text.
    EXPECT_EQ(formatMovingAiMap(back), text);
  }
}

TEST(MovingAiMapTest, FilesGoThroughTheProblemFileFunctionsByExtension) {
  const fs::path dir = fs::temp_directory_path() / ("ppp_movingai_map_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string written = (dir / "written.map").string();
  const Problem p = parseMovingAiMap(kEveryTerrain, "every.map");
  writeProblemFile(p, written);
  EXPECT_EQ(readMovingAiMap(written), p);
  EXPECT_EQ(readProblemFile((dir / "written.map").string()), p);
  MapImportOptions options;
  options.start = Cell{0, 2};
  EXPECT_EQ(readProblemFile(written, options).start, (Cell{0, 2}));

  const std::string missing = (dir / "missing.map").string();
  try {
    readMovingAiMap(missing);
    ADD_FAILURE() << "a missing file was read";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  EXPECT_THROW(writeMovingAiMap(p, (dir / "no" / "such.map").string()), IoError);
  try {
    readProblemFile((dir / "maze.txt").string());
    ADD_FAILURE() << "a .txt file was read";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(e.problem().find(".map (MovingAI)"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(MovingAiMapTest, MessagesNameFileLineAndField) {
  EXPECT_STREQ(parseError("type octile\nheight x\nwidth 5\nmap\n").what(),
               "maze.map:2: height: expected a positive integer, got 'x'");
}

TEST(MovingAiMapTest, BadInputNamesLineFieldAndWhatIsWrong) {
  const std::string header = "type octile\nheight 3\nwidth 5\nmap\n";
  const std::string rows = "@.GO.\nTS@W.\n..W.T\n";
  struct Case {
    std::string text;
    int line;
    std::string field;
    std::string fragment;
  };
  const std::vector<Case> cases = {
      {"", 1, "type", "empty file; expected 'type octile'"},
      {"\n", 1, "type", "expected 'type octile'"},
      {"type grid\nheight 3\nwidth 5\nmap\n" + rows, 1, "type",
       "expected 'octile', the MovingAI grid map type, got 'grid'"},
      {"type octile 8\nheight 3\nwidth 5\nmap\n" + rows, 1, "type", "expected 'type octile', got 'type octile 8'"},
      {"height 3\nwidth 5\nmap\n" + rows, 1, "type", "expected 'type octile' (a MovingAI map begins with the lines"},
      {"type octile\nwidth 5\nheight 3\nmap\n" + rows, 2, "height", "in that order), got 'width 5'"},
      {"type octile\nheight 3\nmap\n" + rows, 3, "width", "expected 'width COLUMNS'"},
      {"type octile\nheight 3\n", 3, "width", "unexpected end of file; expected 'width COLUMNS'"},
      {"type octile\nheight\nwidth 5\nmap\n" + rows, 2, "height", "expected 'height ROWS', got 'height'"},
      {"type octile\nheight 0\nwidth 5\nmap\n" + rows, 2, "height", "expected a positive integer, got '0'"},
      {"type octile\nheight 3\nwidth -5\nmap\n" + rows, 3, "width", "expected a positive integer, got '-5'"},
      {"type octile\nheight 3\nwidth 5.0\nmap\n" + rows, 3, "width", "expected a positive integer, got '5.0'"},
      {"type octile\nheight 1\nwidth 5\nmap\n@.GO.\n", 2, "height", "expected a side in [2, 4096] cells, got '1'"},
      {"type octile\nheight 3\nwidth 4097\nmap\n" + rows, 3, "width", "expected a side in [2, 4096] cells, got '4097'"},
      {"type octile\nheight 99999999999999999999\nwidth 5\nmap\n", 2, "height", "[2, 4096] cells, got '9999"},
      {"type octile\nheight 3\nwidth 5\n" + rows, 4, "map", "expected 'map', the line before the rows, got '@.GO.'"},
      {"type octile\nheight 3\nwidth 5\nmap rows\n" + rows, 4, "map", "got 'map rows'"},
      {"type octile\nheight 3\nwidth 5\n", 4, "map", "unexpected end of file; expected 'map'"},
      {header, 5, "map", "unexpected end of file; expected 3 rows (the height), got 0"},
      {header + "@.GO.\nTS@W.\n", 7, "map", "unexpected end of file; expected 3 rows (the height), got 2"},
      {header + rows + ".....\n", 8, "map", "a row beyond the 3 rows (the height): '.....'"},
      {header + rows + "\n@\n", 9, "map", "a row beyond the 3 rows (the height): '@'"},
      {header + "@.GO.\nTS@W\n..W.T\n", 6, "map", "row 1 has 4 characters, expected 5 (the width)"},
      {header + "@.GO..\nTS@W.\n..W.T\n", 5, "map", "row 0 has 6 characters, expected 5 (the width)"},
      {header + "@.GO.\n\n..W.T\n", 6, "map", "row 1 has 0 characters, expected 5 (the width)"},
      {header + "@.GO.\nTS@W.\n..x.T\n", 7, "map", "unknown terrain character 'x' at column 3, cell (2, 2); expected"},
      {header + "@.GO.\nT @W.\n..W.T\n", 6, "map", "unknown terrain character ' ' at column 2, cell (1, 1)"},
      {header + "@.GO.\nTS@W\t\n..W.T\n", 6, "map", "unknown terrain character '\\x09' at column 5, cell (4, 1)"},
      {header + "@.go.\nTS@W.\n..W.T\n", 5, "map", "unknown terrain character 'g' at column 3"},
      {header + std::string("@.GO\0\nTS@W.\n..W.T\n", 18), 5, "map", "unknown terrain character '\\x00' at column 5"},
  };
  for (const Case& c : cases) {
    const ParseError e = parseError(c.text);
    EXPECT_EQ(e.file(), "maze.map") << c.text;
    EXPECT_EQ(e.line(), c.line) << e.what();
    EXPECT_EQ(e.field(), c.field) << e.what();
    EXPECT_NE(std::string(e.what()).find(c.fragment), std::string::npos) << e.what() << "\nexpected: " << c.fragment;
  }
}

TEST(MovingAiMapTest, AMapTooFragmentedForAnObstacleBudgetIsRefused) {
  // 4096 columns of "@." hold 2048 runs a row; 513 rows hold 1,050,624 > kMaxObstacleBudget (1,048,576).
  std::string text = "type octile\nheight 513\nwidth 4096\nmap\n";
  std::string row;
  for (int x = 0; x < 2048; ++x) row += "@.";
  for (int y = 0; y < 513; ++y) text += row + "\n";
  const ParseError e = parseError(text);
  EXPECT_EQ(e.line(), 0);
  EXPECT_EQ(e.field(), "map");
  EXPECT_NE(std::string(e.what()).find("more than 1048576 horizontal obstacle runs"), std::string::npos) << e.what();
  // One row fewer is exactly the budget, and reads.
  text.resize(text.size() - row.size() - 1);
  text.replace(text.find("height 513"), 10, "height 512");
  EXPECT_EQ(parseMovingAiMap(text, "fragmented.map").max_obstacles, kMaxObstacleBudget);
}

}  // namespace
}  // namespace ppp
