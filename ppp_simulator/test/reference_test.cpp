#include "ppp_simulator/report/reference.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace ppp::simulator {
namespace {

/// `passes` passed and `runs - passes` failed runs of `agent` on PPP `problem` of set "s".
void addRuns(std::vector<agents::EpisodeResult>* results, const std::string& problem, const std::string& agent,
             int passes, int runs) {
  for (int i = 0; i < runs; ++i) {
    agents::EpisodeResult r;
    r.set = "s";
    r.problem = problem;
    r.agent = agent;
    r.run = i;
    r.passed = i < passes;
    results->push_back(r);
  }
}

// By hand: agent "a" passes 0, 1, 1 and 2 of 2 runs on four PPPs: per-PPP rates 0, 0.5, 0.5, 1, mean 0.5, sample
// variance (0.25 + 0 + 0 + 0.25) / 3 = 1/6, so the 95 % half-width is 1.959964 x sqrt(1/6) / sqrt(4) = 0.400076.
// Agent "one" ran one PPP (rate 0.5): no spread to speak of, so only its own mean is within.
PassRateTable table() {
  std::vector<agents::EpisodeResult> results;
  addRuns(&results, "p1", "a", 0, 2);
  addRuns(&results, "p2", "a", 1, 2);
  addRuns(&results, "p3", "a", 1, 2);
  addRuns(&results, "p4", "a", 2, 2);
  addRuns(&results, "p1", "one", 1, 2);
  return computePassRates(results, {"s"}, {"a", "one", "never"});
}

TEST(ReferenceTest, TheMeanAndIts95PercentIntervalOverThePpps) {
  const std::vector<ReferenceComparison> rows =
      compareWithReference(table(), {{"s", "a", 85}, {"s", "a", 95}, {"s", "one", 50}, {"s", "one", 51}, {"s", "never", 10}});
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0].set, "s");
  EXPECT_EQ(rows[0].agent, "a");
  EXPECT_TRUE(rows[0].measured);
  EXPECT_EQ(rows[0].problems, 4);
  EXPECT_DOUBLE_EQ(rows[0].mean, 0.5);
  EXPECT_DOUBLE_EQ(rows[0].reference, 0.85);
  EXPECT_NEAR(rows[0].margin, 0.400076, 1e-6);
  EXPECT_TRUE(rows[0].within());    // 0.35 from the mean
  EXPECT_FALSE(rows[1].within());   // 0.45 from it
  EXPECT_DOUBLE_EQ(rows[2].margin, 0.0);
  EXPECT_TRUE(rows[2].within());
  EXPECT_FALSE(rows[3].within());
  EXPECT_FALSE(rows[4].measured);  // no results: nothing to be within
  EXPECT_EQ(rows[4].problems, 0);
  EXPECT_FALSE(rows[4].within());
}

}  // namespace
}  // namespace ppp::simulator
