#include "ppp_core/movingai_scen.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <sys/stat.h>

#include "ppp_core/error.hpp"

namespace ppp {
namespace {

const char* kTwoScenarios =
    "version 1\n"
    "0\tmaps/dao/tiny.map\t4\t3\t0\t0\t3\t2\t3.82842712\n"
    "\n"
    "1 tiny.map 4 3 3 0 0 2 4.41421356\r\n";

// The message of the ParseError (or other Error) that parsing `text` throws, or "" when it parses.
std::string parseError(const std::string& text) {
  try {
    parseMovingAiScenarios(text, "s.scen");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::string tempDir() {
  char name[] = "/tmp/ppp_scen_test_XXXXXX";
  const char* made = mkdtemp(name);
  EXPECT_NE(made, nullptr);
  return made;
}

void touch(const std::string& path) { std::ofstream(path) << "type octile\n"; }

TEST(MovingAiScenTest, ReadsEveryField) {
  const std::vector<MovingAiScenario> s = parseMovingAiScenarios(kTwoScenarios, "s.scen");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].bucket, 0);
  EXPECT_EQ(s[0].map, "maps/dao/tiny.map");
  EXPECT_EQ(s[0].map_width, 4);
  EXPECT_EQ(s[0].map_height, 3);
  EXPECT_EQ(s[0].start, (Cell{0, 0}));
  EXPECT_EQ(s[0].goal, (Cell{3, 2}));
  EXPECT_DOUBLE_EQ(s[0].optimal_length, 3.82842712);
  EXPECT_EQ(s[0].line, 2);
  // Spaces instead of tabs, a blank line before, \r\n after.
  EXPECT_EQ(s[1].bucket, 1);
  EXPECT_EQ(s[1].start, (Cell{3, 0}));
  EXPECT_EQ(s[1].goal, (Cell{0, 2}));
  EXPECT_DOUBLE_EQ(s[1].optimal_length, 4.41421356);
  EXPECT_EQ(s[1].line, 4);
  EXPECT_TRUE(parseMovingAiScenarios("version 1.0\n", "s.scen").empty());
}

TEST(MovingAiScenTest, BadInputNamesFileLineAndField) {
  EXPECT_EQ(parseError(""), "s.scen:1: version: unexpected end of file; expected 'version 1'");
  EXPECT_EQ(parseError("version 2\n"), "s.scen:1: version: expected 'version 1' (MovingAI scenario file), got 'version'");
  EXPECT_EQ(parseError("type octile\n"),
            "s.scen:1: version: expected 'version 1' (MovingAI scenario file), got 'type'");
  EXPECT_EQ(parseError("version 1\n0 a.map 4 3 0 0 3 2\n"),
            "s.scen:2: scenario: expected 9 fields (bucket, map, width, height, start x, start y, goal x, goal y, "
            "optimal length), got 8");
  EXPECT_EQ(parseError("version 1\n0 a.map 4 3 0 0 3 2 long\n"),
            "s.scen:2: optimal_length: expected a length in [0, 33554432], got 'long'");
  EXPECT_EQ(parseError("version 1\n0 a.map 4 3 0 0 3 2 -1\n"),
            "s.scen:2: optimal_length: expected a length in [0, 33554432], got '-1'");
  EXPECT_EQ(parseError("version 1\n0 a.map 4 3 0 0 3 2 nan\n"),
            "s.scen:2: optimal_length: expected a length in [0, 33554432], got 'nan'");
  // A finding of the fuzz target: a 94-digit length, which the writer's buffer cut short.
  EXPECT_EQ(parseError("version 1\n0 a.map 4 3 0 0 3 2 " + std::string(94, '2') + ".2\n"),
            "s.scen:2: optimal_length: expected a length in [0, 33554432], got '" + std::string(40, '2') + "...'");
  EXPECT_EQ(parseError("version 1\nx a.map 4 3 0 0 3 2 1\n"),
            "s.scen:2: bucket: expected an integer in [0, 1073741824], got 'x'");
  EXPECT_EQ(parseError("version 1\n0 a.map 4 3 -1 0 3 2 1\n"),
            "s.scen:2: start_x: expected an integer in [0, 4096], got '-1'");
  EXPECT_EQ(parseError("version 1\n0 a.map 4 3 0 0 3 3 1\n"),
            "s.scen:2: goal: cell (3, 3) is outside the 4 x 3 map the line names");
  EXPECT_EQ(parseError("version 1\n0 a.map 0 3 0 0 0 0 1\n"), "s.scen:2: width: a map of 0 cells");
  EXPECT_EQ(parseError("version 1\n0 a.map 5000 3 0 0 0 0 1\n"),
            "s.scen:2: width: expected an integer in [0, 4096], got '5000'");
}

TEST(MovingAiScenTest, WriteThenReadGivesTheSameScenarios) {
  const std::string dir = tempDir();
  const std::vector<MovingAiScenario> before = parseMovingAiScenarios(kTwoScenarios, "s.scen");
  writeMovingAiScenarios(before, dir + "/out.scen");
  const std::vector<MovingAiScenario> after = readMovingAiScenarios(dir + "/out.scen");
  ASSERT_EQ(after.size(), before.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    EXPECT_EQ(after[i].bucket, before[i].bucket);
    EXPECT_EQ(after[i].map, before[i].map);
    EXPECT_EQ(after[i].map_width, before[i].map_width);
    EXPECT_EQ(after[i].map_height, before[i].map_height);
    EXPECT_EQ(after[i].start, before[i].start);
    EXPECT_EQ(after[i].goal, before[i].goal);
    EXPECT_DOUBLE_EQ(after[i].optimal_length, before[i].optimal_length);
    EXPECT_EQ(after[i].line, static_cast<int>(i) + 2);
  }
  EXPECT_THROW(readMovingAiScenarios(dir + "/missing.scen"), IoError);
}

TEST(MovingAiScenTest, FindsTheMapWhereTheFileSaysElseBesideItElseInTheMapDirectory) {
  const std::string dir = tempDir();
  mkdir((dir + "/scen").c_str(), 0755);
  mkdir((dir + "/maps").c_str(), 0755);
  const std::string scen = dir + "/scen/a.map.scen";
  touch(dir + "/maps/a.map");
  EXPECT_EQ(findScenarioMap(scen, dir + "/maps/a.map", ""), dir + "/maps/a.map");   // as written
  EXPECT_EQ(findScenarioMap(scen, "dao/a.map", dir + "/maps"), dir + "/maps/a.map");  // in --map-dir
  touch(dir + "/scen/a.map");
  EXPECT_EQ(findScenarioMap(scen, "dao/a.map", dir + "/maps"), dir + "/scen/a.map");  // beside the .scen first
  try {
    findScenarioMap(scen, "dao/b.map", "");
    FAIL() << "no error for a missing map";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), scen + ": map 'dao/b.map' not found (looked at dao/b.map, " + dir +
                                         "/scen/b.map; --map-dir names another place to look)");
  }
}

TEST(MovingAiScenTest, ScenarioMustFitItsMap) {
  Grid grid(4, 3);
  grid.setObstacle(Cell{3, 2}, true);
  MovingAiScenario s = parseMovingAiScenarios(kTwoScenarios, "s.scen")[0];
  try {
    checkScenarioOnMap(s, grid, "s.scen");
    FAIL() << "no error for a goal on an obstacle";
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), "s.scen:2: goal: cell (3, 2) is an obstacle on 'maps/dao/tiny.map'");
  }
  grid.setObstacle(Cell{3, 2}, false);
  EXPECT_NO_THROW(checkScenarioOnMap(s, grid, "s.scen"));
  grid.setObstacle(Cell{0, 0}, true);
  EXPECT_THROW(checkScenarioOnMap(s, grid, "s.scen"), ParseError);
  const Grid wider(5, 3);
  try {
    checkScenarioOnMap(s, wider, "s.scen");
    FAIL() << "no error for a size mismatch";
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()),
              "s.scen:2: width: the line gives a 4 x 3 map, but 'maps/dao/tiny.map' is 5 x 3");
  }
}

}  // namespace
}  // namespace ppp
