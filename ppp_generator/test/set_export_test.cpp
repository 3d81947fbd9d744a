#include "ppp_generator/set_export.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/movingai_map.hpp"
#include "ppp_core/ppp_file.hpp"

namespace ppp {
namespace generator {
namespace {

const double kRoot2 = std::sqrt(2.0);

std::string tempDir() {
  char name[] = "/tmp/ppp_set_export_test_XXXXXX";
  const char* made = mkdtemp(name);
  EXPECT_NE(made, nullptr);
  return made;
}

// Two PPPs whose 8-connected optimal lengths are worked out by hand.
ProblemSet handSet() {
  ProblemSet set;
  set.ids = {"ppp_000", "ppp_001"};
  // Empty 5 x 5, (0,0) -> (4,4): four diagonals, 4 sqrt(2) = 5.657, bucket 1.
  set.problems.push_back(Problem::empty(5, 5, 10));
  // 4 x 3, a vertical bar at x = 1 over rows 0-1, (0,0) -> (3,0):
  //   . # . .
  //   . # . .
  //   . . . .
  // down to (0,2) (2), right to (2,2) (2): every diagonal past the bar would cut its corner; then (3,1) by a
  // diagonal (sqrt 2) and up to (3,0) (1): 5 + sqrt(2) = 6.414, bucket 1.
  Problem bar = Problem::empty(4, 3, 10);
  bar.goal = Cell{3, 0};
  bar.obstacles.push_back(Obstacle{Shape::VerticalBar, 1, 0, 2, 1});
  set.problems.push_back(bar);
  return set;
}

TEST(SetExportTest, ScenariosCarryEachPppsStartGoalAndOctileOptimum) {
  const std::vector<MovingAiScenario> s = setScenarios(handSet());
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].map, "ppp_000.map");
  EXPECT_EQ(s[0].map_width, 5);
  EXPECT_EQ(s[0].start, (Cell{0, 0}));
  EXPECT_EQ(s[0].goal, (Cell{4, 4}));
  EXPECT_NEAR(s[0].optimal_length, 4 * kRoot2, 1e-12);
  EXPECT_EQ(s[0].bucket, 1);
  EXPECT_EQ(s[1].map, "ppp_001.map");
  EXPECT_EQ(s[1].map_height, 3);
  EXPECT_EQ(s[1].goal, (Cell{3, 0}));
  EXPECT_NEAR(s[1].optimal_length, 5 + kRoot2, 1e-12);
  EXPECT_EQ(s[1].bucket, 1);
}

TEST(SetExportTest, MapExportReadsBackAsTheSameGridsAndScenarios) {
  const std::string dir = tempDir();
  const ProblemSet set = handSet();
  const std::vector<std::string> written = exportProblemSet(set, dir, ".map", "hand");
  ASSERT_EQ(written, (std::vector<std::string>{dir + "/ppp_000.map", dir + "/ppp_001.map", dir + "/hand.scen"}));
  const std::vector<MovingAiScenario> scenarios = readMovingAiScenarios(dir + "/hand.scen");
  ASSERT_EQ(scenarios.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const Problem read = readMovingAiMap(dir + "/" + scenarios[i].map);
    const Grid grid = decodeGrid(read);
    EXPECT_EQ(grid, decodeGrid(set.problems[i])) << scenarios[i].map;
    checkScenarioOnMap(scenarios[i], grid, dir + "/hand.scen");
    EXPECT_EQ(scenarios[i].start, set.problems[i].start);
    EXPECT_EQ(scenarios[i].goal, set.problems[i].goal);
  }
  EXPECT_NEAR(scenarios[1].optimal_length, 5 + kRoot2, 1e-8);  // written with 8 decimals
}

TEST(SetExportTest, OtherFormatsAndBadOnes) {
  const std::string dir = tempDir();
  const ProblemSet set = handSet();
  const std::vector<std::string> written = exportProblemSet(set, dir, ".ppp", "hand");
  ASSERT_EQ(written.size(), 2u);  // no .scen
  EXPECT_EQ(readPppFile(written[1]), set.problems[1]);
  try {
    exportProblemSet(set, dir, ".gif", "hand");
    FAIL() << "no error for an unknown format";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(std::string(e.what()), "--format: cannot export to '.gif'; valid: .ppp, .yaml, .map, .png, .bt");
  }
  EXPECT_THROW(exportProblemSet(set, dir + "/missing/deeper", ".map", "hand"), IoError);
}

}  // namespace
}  // namespace generator
}  // namespace ppp
