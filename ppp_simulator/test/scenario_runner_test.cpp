#include "ppp_simulator/scenario_runner.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <deque>
#include <fstream>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/movingai_map.hpp"

namespace ppp {
namespace simulator {
namespace {

const std::string kData = std::string(PPP_TEST_DATA_DIR) + "/movingai";

std::string tempDir() {
  char name[] = "/tmp/ppp_scenario_runner_test_XXXXXX";
  const char* made = mkdtemp(name);
  EXPECT_NE(made, nullptr);
  return made;
}

void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

ScenarioRunOptions agent(const std::string& type) {
  ScenarioRunOptions options;
  options.agent.name = type;
  options.agent.type = type;
  return options;
}

// Fewest 4-connected moves from start to goal by breadth-first search: independent of the astar agent.
int fewestMoves(const Grid& grid, Cell start, Cell goal) {
  std::vector<int> moves(static_cast<std::size_t>(grid.size()), -1);
  std::deque<Cell> queue{start};
  moves[grid.index(start)] = 0;
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    const Cell next[4] = {{c.x, c.y - 1}, {c.x + 1, c.y}, {c.x, c.y + 1}, {c.x - 1, c.y}};
    for (const Cell n : next) {
      if (!grid.isFree(n) || moves[grid.index(n)] >= 0) continue;
      moves[grid.index(n)] = moves[grid.index(c)] + 1;
      queue.push_back(n);
    }
  }
  return moves[grid.index(goal)];
}

TEST(ScenarioRunnerTest, AstarTakesAShortestFourConnectedRouteOnEveryScenarioOfADragonAgeMap) {
  const std::vector<ScenarioResult> results = runScenarios(kData + "/arena.map.scen", agent("astar"));
  ASSERT_EQ(results.size(), 130u);
  const Grid grid = decodeGrid(readMovingAiMap(kData + "/arena.map"));
  const int free_cells = grid.size() - grid.obstacleCount();
  for (const ScenarioResult& r : results) {
    const MovingAiScenario& s = r.scenario;
    EXPECT_TRUE(r.outcome.passed) << "line " << s.line;
    EXPECT_EQ(r.outcome.path_length, fewestMoves(grid, s.start, s.goal)) << "line " << s.line;
    EXPECT_GE(r.outcome.path_length, s.optimal_length - 1e-9) << "line " << s.line;  // 8-connected is shorter
    EXPECT_EQ(r.budget, free_cells);
  }
}

TEST(ScenarioRunnerTest, AstarUnderConnectivityEightReproducesEveryPublishedLength) {
  ScenarioRunOptions options = agent("astar");
  options.episode.connectivity = Connectivity::Eight;
  const std::vector<ScenarioResult> results = runScenarios(kData + "/arena.map.scen", options);
  ASSERT_EQ(results.size(), 130u);
  int with_diagonals = 0;
  for (const ScenarioResult& r : results) {
    EXPECT_TRUE(r.outcome.passed) << "line " << r.scenario.line;
    EXPECT_NEAR(pathLength(r.outcome), r.scenario.optimal_length, 1e-3) << "line " << r.scenario.line;
    with_diagonals += r.outcome.diagonal_moves > 0 ? 1 : 0;
  }
  EXPECT_GT(with_diagonals, 100);
}

TEST(ScenarioRunnerTest, GivenBudgetAndSeedsAreUsed) {
  ScenarioRunOptions options = agent("astar");
  options.episode.budget = 5;
  options.budget_given = true;
  const std::vector<ScenarioResult> results = runScenarios(kData + "/arena.map.scen", options);
  const Grid grid = decodeGrid(readMovingAiMap(kData + "/arena.map"));
  int passed = 0;
  for (const ScenarioResult& r : results) {
    EXPECT_EQ(r.budget, 5);
    // astar passes exactly the scenarios whose shortest route fits in 5 moves.
    EXPECT_EQ(r.outcome.passed, fewestMoves(grid, r.scenario.start, r.scenario.goal) <= 5) << "line " << r.scenario.line;
    passed += r.outcome.passed ? 1 : 0;
  }
  EXPECT_GT(passed, 0);
  EXPECT_LT(passed, 130);
  ScenarioRunOptions random = agent("random");
  random.seed = 9;
  const std::vector<ScenarioResult> a = runScenarios(kData + "/arena.map.scen", random);
  const std::vector<ScenarioResult> b = runScenarios(kData + "/arena.map.scen", random);
  random.seed = 10;
  const std::vector<ScenarioResult> c = runScenarios(kData + "/arena.map.scen", random);
  long steps_a = 0;
  long steps_b = 0;
  long steps_c = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    steps_a += a[i].outcome.steps;
    steps_b += b[i].outcome.steps;
    steps_c += c[i].outcome.steps;
    EXPECT_EQ(a[i].seed, b[i].seed);
    EXPECT_NE(a[i].seed, c[i].seed);
  }
  EXPECT_EQ(steps_a, steps_b);
  EXPECT_NE(steps_a, steps_c);
}

TEST(ScenarioRunnerTest, MapsAreFoundBesideTheFileOrInTheMapDirectory) {
  const std::string dir = tempDir();
  writeText(dir + "/moved.scen", "version 1\n0\tmaps/dao/arena.map\t49\t49\t19\t26\t19\t29\t3.00000000\n");
  try {
    runScenarios(dir + "/moved.scen", agent("astar"));
    FAIL() << "no error for a map nowhere";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(dir + "/moved.scen: map 'maps/dao/arena.map' not found"), std::string::npos)
        << e.what();
  }
  ScenarioRunOptions options = agent("astar");
  options.map_dir = kData;
  ASSERT_EQ(runScenarios(dir + "/moved.scen", options).size(), 1u);
}

TEST(ScenarioRunnerTest, ScenariosOffTheirMapAreErrorsNamingTheLine) {
  const std::string dir = tempDir();
  ScenarioRunOptions options = agent("astar");
  options.map_dir = kData;
  writeText(dir + "/wall.scen", "version 1\n0\tarena.map\t49\t49\t19\t26\t19\t29\t3\n0\tarena.map\t49\t49\t0\t0\t1\t3\t3\n");
  try {
    runScenarios(dir + "/wall.scen", options);
    FAIL() << "no error for a start on an obstacle";
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), dir + "/wall.scen:3: start: cell (0, 0) is an obstacle on 'arena.map'");
  }
  writeText(dir + "/size.scen", "version 1\n0\tarena.map\t50\t49\t19\t26\t19\t29\t3\n");
  EXPECT_THROW(runScenarios(dir + "/size.scen", options), ParseError);
  writeText(dir + "/same.scen", "version 1\n0\tarena.map\t49\t49\t19\t26\t19\t26\t0\n");
  try {
    runScenarios(dir + "/same.scen", options);
    FAIL() << "no error for start = goal";
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), dir + "/same.scen:2: goal: equals the start");
  }
}

}  // namespace
}  // namespace simulator
}  // namespace ppp
