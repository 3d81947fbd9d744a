// Detour figures of passed runs, worked by hand on a few rows.

#include "ppp_simulator/report/detours.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ppp_core/error.hpp"

namespace ppp::simulator {
namespace {

agents::EpisodeResult row(const std::string& problem, int run, bool passed, double path, double optimal,
                          bool soft = false) {
  agents::EpisodeResult r;
  r.set = "s";
  r.problem = problem;
  r.agent = "explorer";
  r.run = run;
  r.passed = passed;
  r.path_length = path;
  r.optimal_length = optimal;
  r.soft_failure = soft;
  return r;
}

TEST(DetourStatsTest, PercentilesWorstPppAndLongestRunWorkedByHand) {
  // p1 (optimum 10): passed in 10, 20 and 30 (ratios 1, 2, 3), one failed run (left out).
  // p2 (optimum 20): passed in 40 twice (ratio 2; the lower run number is the longest of equals), 60 a soft one.
  const std::vector<agents::EpisodeResult> rows = {
      row("p1", 0, true, 10, 10), row("p1", 1, true, 20, 10), row("p1", 2, true, 30, 10), row("p1", 3, false, 5, 10),
      row("p2", 1, true, 40, 20), row("p2", 0, true, 40, 20), row("p2", 2, true, 60, 20, true),
      row("p3", 0, true, 7, -1)};  // no known optimum: left out
  const std::vector<DetourStats> stats = detourStats(rows, {"s"}, {"astar", "explorer"});
  ASSERT_EQ(stats.size(), 1u);  // astar has no rows
  const DetourStats& d = stats[0];
  EXPECT_EQ(d.agent, "explorer");
  EXPECT_EQ(d.passed, 6);
  EXPECT_EQ(d.soft_failures, 1);
  // Sorted ratios 1, 2, 2, 2, 3, 3: the median between the 3rd and 4th is 2; the 5th percentile at 0.25 of the
  // way from the 1st to the 2nd is 1.25; the quartiles at 1.25 and 3.75 are 2 and 2.75; the 95th at 4.75 is 3.
  EXPECT_DOUBLE_EQ(d.spread.median, 2);
  EXPECT_DOUBLE_EQ(d.spread.p5, 1.25);
  EXPECT_DOUBLE_EQ(d.spread.p25, 2);
  EXPECT_DOUBLE_EQ(d.spread.p75, 2.75);
  EXPECT_DOUBLE_EQ(d.spread.p95, 3);
  EXPECT_DOUBLE_EQ(d.max, 3);
  // Means: p1 (1 + 2 + 3) / 3 = 2; p2 (2 + 2 + 3) / 3 = 7/3: p2 is the worst, its longest run is run 2.
  EXPECT_EQ(d.worst_problem, "p2");
  EXPECT_NEAR(d.worst_mean, 7.0 / 3, 1e-12);
  ASSERT_NE(d.longest, nullptr);
  EXPECT_EQ(d.longest->run, 2);
}

TEST(DetourStatsTest, RowsOutsideTheOrdersAreRefused) {
  EXPECT_THROW(detourStats({row("p1", 0, true, 10, 10)}, {"other"}, {"explorer"}), InvalidArgument);
}

}  // namespace
}  // namespace ppp::simulator
