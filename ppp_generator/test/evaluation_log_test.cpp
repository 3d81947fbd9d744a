#include "ppp_generator/evaluation_log.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "ppp_generator/set_evolution.hpp"

namespace ppp {
namespace generator {
namespace {

/// The lines of a text.
std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(EvaluationLogTest, AHuntLogsEveryPppItScoredInOrderWithItsFigures) {
  // A batch scorer: value = obstacle cells, failed = more than 40 of them; it keeps what it was given.
  std::vector<std::string> expected;
  Fitness fitness;
  fitness.name = "obstacle_cells";
  fitness.batch_size = 8;
  fitness.batch = [&expected](const std::vector<const Problem*>&, const std::vector<const Grid*>& grids) {
    std::vector<FitnessScore> scores;
    for (const Grid* g : grids) {
      const int cells = g->obstacleCount();
      scores.push_back({double(cells), double(cells), cells > 40 ? 1.0 : 0.0});
      scores.back().steps = 7L * cells;
      char hash[17];
      std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(g->hash()));
      expected.push_back(std::to_string(expected.size() + 1) + "," + std::to_string(cells) + "," +
                         (cells > 40 ? "1" : "0") + "," + hash + "," + std::to_string(7 * cells));
    }
    return scores;
  };
  GeneratorOptions options;  // the set is named after `turns`; the batch scorer above scores it
  options.population = 10;
  options.matings = 40;
  options.seed = 3;
  const EvolvedSet evolved = evolveSet(options, fitness);
  const auto log = evolved.extra_files.find(kEvaluationLogFile);
  ASSERT_NE(log, evolved.extra_files.end());
  const std::vector<std::string> rows = linesOf(withoutSeconds(log->second));
  ASSERT_GE(expected.size(), 10u);  // the initial pool at least
  ASSERT_EQ(rows.size(), expected.size() + 1);
  EXPECT_EQ(rows[0], "evaluation,value,failure_rate,grid,steps");
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(rows[i + 1], expected[i]) << i;
  // The seconds column: non-negative and never decreasing.
  double last = 0;
  for (const std::string& row : linesOf(log->second)) {
    if (row.rfind("evaluation", 0) == 0) continue;
    const double seconds = std::stod(row.substr(row.find(',') + 1));
    EXPECT_GE(seconds, last);
    last = seconds;
  }
}

TEST(EvaluationLogTest, AFitnessScoredByValueWritesNoLog) {
  GeneratorOptions options;
  options.fitness = "turns";
  options.population = 10;
  options.matings = 20;
  const EvolvedSet evolved = evolveSet(options, makeFitness("turns"));
  EXPECT_EQ(evolved.extra_files.count(kEvaluationLogFile), 0u);
}

TEST(EvaluationLogTest, WithoutSecondsDropsTheSecondColumnOfEveryLine) {
  EXPECT_EQ(withoutSeconds("evaluation,seconds,value\n1,0.250,3\n2,1.500,4\n"), "evaluation,value\n1,3\n2,4\n");
}

}  // namespace
}  // namespace generator
}  // namespace ppp
