#include "ppp_core/rng.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace ppp {
namespace {

TEST(RngTest, SameSeedSameSequence) {
  Rng a(42), b(42), c(43);
  bool differs = false;
  for (int i = 0; i < 100; ++i) {
    const auto va = a.next();
    EXPECT_EQ(va, b.next());
    differs |= va != c.next();
  }
  EXPECT_TRUE(differs);
}

TEST(RngTest, UniformIntCoversRangeEvenly) {
  // Chi-square over 6 faces with 60,000 draws; the 0.999 quantile for 5 d.o.f. is 20.5.
  Rng rng(7);
  std::vector<int> counts(6, 0);
  const int draws = 60000;
  for (int i = 0; i < draws; ++i) {
    const auto v = rng.uniformInt(-2, 3);
    ASSERT_GE(v, -2);
    ASSERT_LE(v, 3);
    ++counts[v + 2];
  }
  double chi2 = 0;
  for (int c : counts) chi2 += (c - draws / 6.0) * (c - draws / 6.0) / (draws / 6.0);
  EXPECT_LT(chi2, 20.5);
}

TEST(RngTest, Uniform01AndBernoulli) {
  Rng rng(9);
  int hits = 0;
  const int draws = 100000;
  for (int i = 0; i < draws; ++i) {
    const double u = rng.uniform01();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    hits += rng.bernoulli(0.3) ? 1 : 0;
  }
  // Binomial(100000, 0.3): standard deviation 144.9; allow 4 of them.
  EXPECT_NEAR(hits, 30000, 4 * 145);
  EXPECT_FALSE(rng.bernoulli(0.0));
  EXPECT_TRUE(rng.bernoulli(1.0));
}

TEST(RngTest, DerivedSeedsAreDistinctAndStable) {
  EXPECT_EQ(deriveSeed(1, {2, 3}), deriveSeed(1, {2, 3}));
  EXPECT_NE(deriveSeed(1, {2, 3}), deriveSeed(1, {3, 2}));
  EXPECT_NE(deriveSeed(1, {2}), deriveSeed(1, {2, 0}));
  EXPECT_NE(deriveSeed(1, {0}), deriveSeed(2, {0}));
}

}  // namespace
}  // namespace ppp
