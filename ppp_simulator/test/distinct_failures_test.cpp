#include "ppp_simulator/report/distinct_failures.hpp"

#include <gtest/gtest.h>

namespace ppp {
namespace simulator {
namespace {

TEST(FailureGroupingTest, CountsEachKindAndKeepsItsSmallestMap) {
  FailureGrouping grouping;
  grouping.add("loop2/g1/s8-15/t1/w2e0/G1e0d1", "turns/ppp_003", 40, 0);
  grouping.add("stuck/g4-7/s4-7/t1/w3e0", "turns/ppp_001", 12, 1);
  grouping.add("loop2/g1/s8-15/t1/w2e0/G1e0d1", "turns/ppp_007", 25, 2);
  grouping.add("loop2/g1/s8-15/t1/w2e0/G1e0d1", "turns/ppp_007", 25, 3);  // another run on the same map
  grouping.add("stuck/g4-7/s4-7/t1/w3e0", "turns/ppp_009", 12, 4);        // as small: the first stays
  grouping.add("missed_route/g32-63/s0/t0/w0e2", "turns/ppp_002", 30, 5);
  EXPECT_EQ(grouping.total(), 6);
  const std::vector<DistinctFailure> kinds = grouping.groups();
  ASSERT_EQ(kinds.size(), 3u);
  EXPECT_EQ(kinds[0].key, "loop2/g1/s8-15/t1/w2e0/G1e0d1");
  EXPECT_EQ(kinds[0].count, 3);
  EXPECT_EQ(kinds[0].places, 2);
  EXPECT_EQ(kinds[0].smallest, 2u);
  EXPECT_EQ(kinds[0].smallest_cells, 25);
  EXPECT_EQ(kinds[1].key, "stuck/g4-7/s4-7/t1/w3e0");
  EXPECT_EQ(kinds[1].count, 2);
  EXPECT_EQ(kinds[1].smallest, 1u);
  EXPECT_EQ(kinds[2].count, 1);
  EXPECT_EQ(kinds[2].smallest_cells, 30);
}

TEST(FailureGroupingTest, EqualCountsKeepTheOrderTheyWereFirstMet) {
  FailureGrouping grouping;
  for (const char* key : {"c", "a", "b"}) grouping.add(key, key, 1, 0);
  const std::vector<DistinctFailure> kinds = grouping.groups();
  ASSERT_EQ(kinds.size(), 3u);
  EXPECT_EQ(kinds[0].key, "c");
  EXPECT_EQ(kinds[1].key, "a");
  EXPECT_EQ(kinds[2].key, "b");
  EXPECT_TRUE(FailureGrouping().groups().empty());
}

TEST(FailureGroupingTest, ALineSaysCountMapsKindSmallestAndReplay) {
  DistinctFailure kind{"stuck/g4-7/s4-7/t1/w3e0", 3, 2, 0, 12};
  EXPECT_EQ(distinctFailureLine(kind, "run", "stuck", "turns/ppp_001", "ppp replay a.ppp --agent bumper --seed 5"),
            "  3 runs on 2 PPPs: stuck/g4-7/s4-7/t1/w3e0 (stuck); smallest turns/ppp_001, 12 obstacle cells; "
            "replay: ppp replay a.ppp --agent bumper --seed 5");
  kind = DistinctFailure{"trap_00ff", 1, 1, 0, 1};
  EXPECT_EQ(distinctFailureLine(kind, "PPP", "", "ppp_004.ppp", ""),
            "  1 PPP: trap_00ff; smallest ppp_004.ppp, 1 obstacle cell");
}

}  // namespace
}  // namespace simulator
}  // namespace ppp
