#include "ppp_simulator/report/pass_rates.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>
#include <unistd.h>

#include "ppp_core/error.hpp"
#include "ppp_core/text_file.hpp"

namespace ppp::simulator {
namespace {

agents::EpisodeResult run(const std::string& set, const std::string& problem, const std::string& agent, bool passed,
                  int steps) {
  agents::EpisodeResult r;
  r.set = set;
  r.problem = problem;
  r.agent = agent;
  r.passed = passed;
  r.steps = steps;
  r.reason = passed ? reason::kGoalReached : reason::kBudgetExhausted;
  return r;
}

/// `r` marked as a soft failure.
agents::EpisodeResult soft(agents::EpisodeResult r) {
  r.soft_failure = true;
  r.diagnosis = diagnosis::kDetour;
  return r;
}

/// `r` diagnosed as `kind`; a loop with period 2, endless when `endless`.
agents::EpisodeResult diagnosed(agents::EpisodeResult r, const char* kind, bool endless = false) {
  r.diagnosis = kind;
  r.diagnosis_step = 10;
  if (std::string(kind) == diagnosis::kLoop) r.loop_period = 2;
  if (endless) r.endless_step = 12;
  return r;
}

// By hand (orders: sets hard, easy, unused; agents random, astar):
//   hard/h1:  random 2 of 3 (0.666667; one of the two a soft failure, a detour; the failure an endless loop),
//             astar 3 of 3
//   hard/h2:  astar 1 of 1; random never ran it
//   easy/p2:  random 1 of 4 (0.25, steps 10 + 300·3 → mean 227.5; the failures a loop and two confined),
//             astar 4 of 4 (8 steps each)
//   easy/p10: random 0 of 1 (stuck), astar 2 of 2
//   set rates (mean of per-PPP rates): hard/random 0.666667 (1 PPP), hard/astar 1 (2 PPPs),
//   easy/random (0.25 + 0)/2 = 0.125 — not the pooled 1/5 = 0.2 — and easy/astar 1.
std::vector<agents::EpisodeResult> handMadeResults() {
  return {
      run("easy", "p10", "astar", true, 12), run("hard", "h1", "random", true, 40),
      diagnosed(run("easy", "p2", "random", false, 300), diagnosis::kLoop), run("easy", "p2", "astar", true, 8),
      run("hard", "h2", "astar", true, 20),   run("easy", "p2", "random", true, 10),
      run("hard", "h1", "astar", true, 18),   run("easy", "p2", "astar", true, 8),
      diagnosed(run("hard", "h1", "random", false, 300), diagnosis::kLoop, true),
      diagnosed(run("easy", "p10", "random", false, 300), diagnosis::kStuck),
      diagnosed(run("easy", "p2", "random", false, 300), diagnosis::kConfined), run("hard", "h1", "astar", true, 18),
      run("easy", "p2", "astar", true, 8),    soft(run("hard", "h1", "random", true, 60)),
      diagnosed(run("easy", "p2", "random", false, 300), diagnosis::kConfined), run("easy", "p10", "astar", true, 12),
      run("hard", "h1", "astar", true, 18),   run("easy", "p2", "astar", true, 8),
  };
}

PassRateTable handMadeTable() {
  return computePassRates(handMadeResults(), {"hard", "easy", "unused"}, {"random", "astar"});
}

TEST(ComputePassRates, PerProblemRowsFollowSetOrderNaturalIdOrderAndAgentOrder) {
  const PassRateTable table = handMadeTable();
  struct Expected {
    const char* set;
    const char* problem;
    const char* agent;
    int runs;
    int passes;
    double rate;
    double mean_steps;
  };
  const Expected expected[] = {
      {"hard", "h1", "random", 3, 2, 2.0 / 3, (40 + 300 + 60) / 3.0},
      {"hard", "h1", "astar", 3, 3, 1.0, 18},
      {"hard", "h2", "astar", 1, 1, 1.0, 20},
      {"easy", "p2", "random", 4, 1, 0.25, 227.5},
      {"easy", "p2", "astar", 4, 4, 1.0, 8},
      {"easy", "p10", "random", 1, 0, 0.0, 300},
      {"easy", "p10", "astar", 2, 2, 1.0, 12},
  };
  ASSERT_EQ(table.per_problem.size(), std::size(expected));
  for (std::size_t i = 0; i < std::size(expected); ++i) {
    const ProblemPassRate& row = table.per_problem[i];
    SCOPED_TRACE("row " + std::to_string(i));
    EXPECT_EQ(row.set, expected[i].set);
    EXPECT_EQ(row.problem, expected[i].problem);
    EXPECT_EQ(row.agent, expected[i].agent);
    EXPECT_EQ(row.runs, expected[i].runs);
    EXPECT_EQ(row.passes, expected[i].passes);
    EXPECT_DOUBLE_EQ(row.rate(), expected[i].rate);
    EXPECT_DOUBLE_EQ(row.mean_steps, expected[i].mean_steps);
  }
  EXPECT_EQ(table.sets, (std::vector<std::string>{"hard", "easy", "unused"}));
  EXPECT_EQ(table.agents, (std::vector<std::string>{"random", "astar"}));
}

TEST(ComputePassRates, SetRateIsTheMeanOfPerPppRatesNotThePooledShare) {
  const PassRateTable table = handMadeTable();
  ASSERT_EQ(table.per_set.size(), 4u);  // nothing for the set without results
  const SetPassRate* easy_random = table.find("easy", "random");
  ASSERT_NE(easy_random, nullptr);
  EXPECT_EQ(easy_random->problems, 2);
  EXPECT_EQ(easy_random->runs, 5);
  EXPECT_EQ(easy_random->passes, 1);
  EXPECT_DOUBLE_EQ(easy_random->mean_rate, 0.125);

  const SetPassRate* hard_random = table.find("hard", "random");
  ASSERT_NE(hard_random, nullptr);
  EXPECT_EQ(hard_random->problems, 1);
  EXPECT_DOUBLE_EQ(hard_random->mean_rate, 2.0 / 3);

  const SetPassRate* hard_astar = table.find("hard", "astar");
  ASSERT_NE(hard_astar, nullptr);
  EXPECT_EQ(hard_astar->problems, 2);
  EXPECT_EQ(hard_astar->runs, 4);
  EXPECT_DOUBLE_EQ(hard_astar->mean_rate, 1.0);

  EXPECT_EQ(table.find("unused", "astar"), nullptr);
  EXPECT_EQ(table.find("easy", "nobody"), nullptr);

  // Set order, then agent order.
  EXPECT_EQ(table.per_set[0].set, "hard");
  EXPECT_EQ(table.per_set[0].agent, "random");
  EXPECT_EQ(table.per_set[3].set, "easy");
  EXPECT_EQ(table.per_set[3].agent, "astar");
}

TEST(ComputePassRates, ProblemRatesListsOneRatePerPpp) {
  const PassRateTable table = handMadeTable();
  EXPECT_EQ(table.problemRates("easy", "random"), (std::vector<double>{0.25, 0.0}));
  EXPECT_EQ(table.problemRates("hard", "astar"), (std::vector<double>{1.0, 1.0}));
  EXPECT_TRUE(table.problemRates("unused", "astar").empty());
}

TEST(ComputePassRates, NoResultsGiveEmptyTables) {
  const PassRateTable table = computePassRates({}, {"a"}, {"x"});
  EXPECT_TRUE(table.per_problem.empty());
  EXPECT_TRUE(table.per_set.empty());
  EXPECT_EQ(ProblemPassRate{}.rate(), 0.0);
}

TEST(ComputePassRates, RejectsNamesOutsideTheOrdersAndBadOrders) {
  const auto expectName = [](const auto& call, const std::string& name) {
    try {
      call();
      ADD_FAILURE() << "expected InvalidArgument naming " << name;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.name(), name) << e.what();
    }
  };
  expectName([] { computePassRates({run("other", "p", "x", true, 1)}, {"a"}, {"x"}); }, "results");
  expectName([] { computePassRates({run("a", "p", "y", true, 1)}, {"a"}, {"x"}); }, "results");
  expectName([] { computePassRates({run("a", "", "x", true, 1)}, {"a"}, {"x"}); }, "results");
  expectName([] { computePassRates({}, {"a", "a"}, {"x"}); }, "set_order");
  expectName([] { computePassRates({}, {"a"}, {""}); }, "agent_order");
}

TEST(NaturalLess, ComparesDigitRunsAsNumbers) {
  EXPECT_TRUE(naturalLess("p2", "p10"));
  EXPECT_FALSE(naturalLess("p10", "p2"));
  EXPECT_TRUE(naturalLess("ppp_9", "ppp_10"));
  EXPECT_TRUE(naturalLess("a", "b"));
  EXPECT_TRUE(naturalLess("p1", "p1a"));
  EXPECT_FALSE(naturalLess("p1", "p1"));
  // Equal as numbers but different ids: still a strict order.
  EXPECT_NE(naturalLess("p01", "p1"), naturalLess("p1", "p01"));
}

/// A directory `<name>_<process id>` under the system temporary directory, created.
std::string tempDir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir.string();
}

TEST(WriteSummaryCsv, WritesProblemRowsThenSetRows) {
  const std::string dir = tempDir("pass_rates_test");
  const std::string path = dir + "/summary.csv";
  writeSummaryCsv(path, handMadeTable());
  EXPECT_EQ(readTextFile(path, 1 << 20),
            "level,set,problem,agent,problems,runs,passes,pass_rate,soft_failures,stuck,loop,confined,wandering,"
            "detour,missed_route,no_route,reported,endless_loops\n"
            "problem,hard,h1,random,1,3,2,0.666667,1,0,1,0,0,1,0,0,0,1\n"
            "problem,hard,h1,astar,1,3,3,1,0,0,0,0,0,0,0,0,0,0\n"
            "problem,hard,h2,astar,1,1,1,1,0,0,0,0,0,0,0,0,0,0\n"
            "problem,easy,p2,random,1,4,1,0.25,0,0,1,2,0,0,0,0,0,0\n"
            "problem,easy,p2,astar,1,4,4,1,0,0,0,0,0,0,0,0,0,0\n"
            "problem,easy,p10,random,1,1,0,0,0,1,0,0,0,0,0,0,0,0\n"
            "problem,easy,p10,astar,1,2,2,1,0,0,0,0,0,0,0,0,0,0\n"
            "set,hard,,random,1,3,2,0.666667,1,0,1,0,0,1,0,0,0,1\n"
            "set,hard,,astar,2,4,4,1,0,0,0,0,0,0,0,0,0,0\n"
            "set,easy,,random,2,5,1,0.125,0,1,1,2,0,0,0,0,0,0\n"
            "set,easy,,astar,2,6,6,1,0,0,0,0,0,0,0,0,0,0\n");
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  std::filesystem::remove_all(dir);
}

TEST(WriteSummaryCsv, QuotesNamesWithCommas) {
  const std::string dir = tempDir("pass_rates_quote_test");
  const std::string path = dir + "/summary.csv";
  writeSummaryCsv(path, computePassRates({run("a,b", "p", "x", true, 1)}, {"a,b"}, {"x"}));
  const std::string text = readTextFile(path, 1 << 20);
  EXPECT_NE(text.find("problem,\"a,b\",p,x,1,1,1,1,0,0,0,0,0,0,0,0,0,0\n"), std::string::npos) << text;
  std::filesystem::remove_all(dir);
}

TEST(WriteSummaryCsv, UnwritablePathThrowsIoError) {
  EXPECT_THROW(writeSummaryCsv("/nonexistent-dir-for-ppp-test/summary.csv", handMadeTable()), IoError);
}

}  // namespace
}  // namespace ppp::simulator
