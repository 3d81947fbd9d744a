#include "ppp_simulator/report/statistics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"

namespace ppp::simulator {
namespace {

// Worked example with ties, by hand (values as per-PPP pass rates):
//   a = {0.9, 0.7, 0.7, 1.0, 0.5}   n_a = 5
//   b = {0.4, 0.7, 0.2, 0.5, 0.1, 0.3}   n_b = 6,   N = 11
//
//   value  0.1 0.2 0.3 0.4 0.5 0.5 0.7 0.7 0.7 0.9 1.0
//   from    b   b   b   b   a   b   a   a   b   a   a
//   rank    1   2   3   4  5.5 5.5  8   8   8  10  11      (0.5 shares ranks 5,6; 0.7 shares 7,8,9)
//
//   R_a = 5.5 + 8 + 8 + 10 + 11 = 42.5      U_a = 42.5 − 5·6/2 = 27.5
//   R_b = 1 + 2 + 3 + 4 + 5.5 + 8 = 23.5    U_b = 23.5 − 6·7/2 = 2.5     (U_a + U_b = 30 = n_a n_b)
//   U = min = 2.5
//   ties: t = 2 (0.5) and t = 3 (0.7): Σ(t³ − t) = 6 + 24 = 30
//   σ² = 5·6/12 · ((11 + 1) − 30/(11·10)) = 2.5 · (12 − 0.272727) = 2.5 · 11.727273 = 29.318182
//   σ = 5.4146
//   z = (27.5 − 15) / 5.4146 = 2.3086
//   p = 2·(1 − Φ(2.3086)) = erfc(2.3086/√2) = erfc(1.6324) = 0.0210
//       (tables: Φ(2.30) = 0.98928, Φ(2.31) = 0.98956 → Φ(2.3086) ≈ 0.98952 → p ≈ 0.0210)
TEST(MannWhitneyU, MatchesTheHandComputedExampleWithTies) {
  const MannWhitney r = mannWhitneyU({0.9, 0.7, 0.7, 1.0, 0.5}, {0.4, 0.7, 0.2, 0.5, 0.1, 0.3});
  EXPECT_EQ(r.n_a, 5);
  EXPECT_EQ(r.n_b, 6);
  EXPECT_DOUBLE_EQ(r.u_a, 27.5);
  EXPECT_DOUBLE_EQ(r.u_b, 2.5);
  EXPECT_DOUBLE_EQ(r.u, 2.5);
  EXPECT_NEAR(r.z, 2.3086, 5e-5);
  EXPECT_NEAR(r.p, 0.0210, 5e-5);
  // σ, recovered from z, is the tie-corrected one (without the correction σ² would be 30, σ = 5.4772).
  EXPECT_NEAR((r.u_a - 15) / r.z, 5.4146, 5e-5);
}

// Worked example without ties:
//   a = {3, 5, 8}, b = {1, 2, 4, 6}: ranks 1 2 [3] 4 [5] 6 [7] (a in brackets)
//   R_a = 3 + 5 + 7 = 15, U_a = 15 − 3·4/2 = 9, U_b = 12 − 9 = 3, U = 3
//   σ² = 3·4·(7 + 1)/12 = 8, σ = 2√2 = 2.8284
//   z = (9 − 6)/(2√2) = 1.0607, z/√2 = 0.75 exactly, p = erfc(0.75) = 0.2888
TEST(MannWhitneyU, MatchesTheHandComputedExampleWithoutTies) {
  const MannWhitney r = mannWhitneyU({3, 5, 8}, {1, 2, 4, 6});
  EXPECT_DOUBLE_EQ(r.u_a, 9);
  EXPECT_DOUBLE_EQ(r.u_b, 3);
  EXPECT_DOUBLE_EQ(r.u, 3);
  EXPECT_NEAR(r.z, 1.0607, 5e-5);
  EXPECT_NEAR(r.p, 0.2888, 5e-5);
}

/// U_a by counting pairs: a_i > b_j counts 1, a_i == b_j counts one half.
double bruteForceU(const std::vector<double>& a, const std::vector<double>& b) {
  double u = 0;
  for (const double x : a) {
    for (const double y : b) u += x > y ? 1.0 : x == y ? 0.5 : 0.0;
  }
  return u;
}

TEST(MannWhitneyU, UEqualsPairCountOnRandomSamplesWithoutTies) {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> value(0.0, 1.0);
  std::uniform_int_distribution<int> size(1, 25);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> a(static_cast<std::size_t>(size(rng)));
    std::vector<double> b(static_cast<std::size_t>(size(rng)));
    for (double& x : a) x = value(rng);
    for (double& x : b) x = value(rng);
    const MannWhitney r = mannWhitneyU(a, b);
    ASSERT_NEAR(r.u_a, bruteForceU(a, b), 1e-9) << "trial " << trial;
    ASSERT_NEAR(r.u_b, bruteForceU(b, a), 1e-9) << "trial " << trial;
    // Without ties the variance is the plain n_a n_b (N + 1) / 12.
    const double n_a = static_cast<double>(a.size());
    const double n_b = static_cast<double>(b.size());
    const double sigma = std::sqrt(n_a * n_b * (n_a + n_b + 1) / 12);
    ASSERT_NEAR(r.z, (r.u_a - n_a * n_b / 2) / sigma, 1e-9) << "trial " << trial;
  }
}

TEST(MannWhitneyU, UEqualsPairCountOnRandomSamplesWithTies) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> value(0, 4);  // few distinct values: many ties
  std::uniform_int_distribution<int> size(1, 15);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> a(static_cast<std::size_t>(size(rng)));
    std::vector<double> b(static_cast<std::size_t>(size(rng)));
    for (double& x : a) x = value(rng) / 4.0;
    for (double& x : b) x = value(rng) / 4.0;
    const MannWhitney r = mannWhitneyU(a, b);
    ASSERT_NEAR(r.u_a, bruteForceU(a, b), 1e-9) << "trial " << trial;
    ASSERT_NEAR(r.u_a + r.u_b, static_cast<double>(a.size() * b.size()), 1e-9);
    ASSERT_GE(r.p, 0.0);
    ASSERT_LE(r.p, 1.0);
  }
}

TEST(MannWhitneyU, SwappingTheSamplesFlipsZAndKeepsP) {
  const std::vector<double> a = {0.9, 0.7, 0.7, 1.0, 0.5};
  const std::vector<double> b = {0.4, 0.7, 0.2, 0.5, 0.1, 0.3};
  const MannWhitney ab = mannWhitneyU(a, b);
  const MannWhitney ba = mannWhitneyU(b, a);
  EXPECT_DOUBLE_EQ(ba.u_a, ab.u_b);
  EXPECT_DOUBLE_EQ(ba.u_b, ab.u_a);
  EXPECT_DOUBLE_EQ(ba.u, ab.u);
  EXPECT_NEAR(ba.z, -ab.z, 1e-12);
  EXPECT_NEAR(ba.p, ab.p, 1e-12);
}

TEST(MannWhitneyU, AllValuesTiedGivesZZeroAndPOne) {
  const MannWhitney r = mannWhitneyU({1, 1, 1}, {1, 1});
  EXPECT_DOUBLE_EQ(r.u_a, 3);
  EXPECT_DOUBLE_EQ(r.u_b, 3);
  EXPECT_EQ(r.z, 0);
  EXPECT_EQ(r.p, 1);
  const MannWhitney single = mannWhitneyU({0.5}, {0.5});
  EXPECT_EQ(single.z, 0);
  EXPECT_EQ(single.p, 1);
}

TEST(MannWhitneyU, IdenticalSamplesGiveZZero) {
  const MannWhitney r = mannWhitneyU({0.1, 0.2, 0.3}, {0.1, 0.2, 0.3});
  EXPECT_DOUBLE_EQ(r.u_a, 4.5);
  EXPECT_NEAR(r.z, 0, 1e-12);
  EXPECT_NEAR(r.p, 1, 1e-12);
}

TEST(MannWhitneyU, EmptyOrNonFiniteSampleIsRejectedByName) {
  try {
    mannWhitneyU({}, {1});
    FAIL() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "a");
  }
  try {
    mannWhitneyU({1}, {});
    FAIL() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "b");
  }
  try {
    mannWhitneyU({1}, {std::nan("")});
    FAIL() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "b");
  }
}

agents::EpisodeResult result(const std::string& set, const std::string& problem, const std::string& agent, bool passed) {
  agents::EpisodeResult r;
  r.set = set;
  r.problem = problem;
  r.agent = agent;
  r.passed = passed;
  return r;
}

TEST(CompareSets, TestsEachAgentsPerPppRatesBetweenTheSets) {
  // One run per PPP, so per-PPP rates are 0 or 1. "good" passes all of A and none of B; "odd" has no B results.
  std::vector<agents::EpisodeResult> results;
  for (const char* p : {"p1", "p2", "p3"}) {
    results.push_back(result("A", p, "good", true));
    results.push_back(result("A", p, "odd", false));
  }
  for (const char* p : {"q1", "q2", "q3", "q4"}) results.push_back(result("B", p, "good", false));
  const PassRateTable table = computePassRates(results, {"A", "B"}, {"good", "odd"});

  const std::vector<AgentComparison> rows = compareSets(table, "A", "B");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].agent, "good");
  EXPECT_DOUBLE_EQ(rows[0].mean_a, 1.0);
  EXPECT_DOUBLE_EQ(rows[0].mean_b, 0.0);
  const MannWhitney direct = mannWhitneyU({1, 1, 1}, {0, 0, 0, 0});
  EXPECT_DOUBLE_EQ(rows[0].test.u_a, 12);
  EXPECT_DOUBLE_EQ(rows[0].test.z, direct.z);
  EXPECT_DOUBLE_EQ(rows[0].test.p, direct.p);
  EXPECT_GT(rows[0].test.z, 0);
}

TEST(CompareSets, UnknownSetIsNamed) {
  const PassRateTable table = computePassRates({result("A", "p1", "x", true)}, {"A", "B"}, {"x"});
  try {
    compareSets(table, "A", "C");
    FAIL() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "set_b");
    EXPECT_NE(std::string(e.what()).find("'C'"), std::string::npos) << e.what();
  }
  try {
    compareSets(table, "Z", "A");
    FAIL() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "set_a");
    EXPECT_NE(std::string(e.what()).find("'Z'"), std::string::npos) << e.what();
  }
  // A known set without results for anyone: no rows, no error.
  EXPECT_TRUE(compareSets(table, "A", "B").empty());
}

}  // namespace
}  // namespace ppp::simulator
