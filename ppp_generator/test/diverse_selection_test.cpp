#include "ppp_generator/diverse_selection.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/rng.hpp"

namespace ppp::generator {
namespace {

Eigen::MatrixXd randomDistances(Rng& rng, int n) {
  Eigen::MatrixXd points(n, 14);
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < 14; ++c) points(r, c) = rng.uniform01();
  }
  return euclideanDistances(points);
}

TEST(DiverseSelectionTest, OneDistinctPickPerCluster) {
  Rng rng(31);
  const Eigen::MatrixXd d = randomDistances(rng, 40);
  const Tree tree = upgma(d);
  for (const int k : {1, 2, 3, 7, 20, 39, 40}) {
    SCOPED_TRACE("k = " + std::to_string(k));
    const std::vector<int> picks = selectDiverse(tree, d, k);
    const std::vector<std::vector<int>> clusters = cutIntoClusters(tree, k);
    ASSERT_EQ(picks.size(), static_cast<std::size_t>(k));
    EXPECT_EQ(std::set<int>(picks.begin(), picks.end()).size(), picks.size());
    for (int c = 0; c < k; ++c) {
      const auto& members = clusters[static_cast<std::size_t>(c)];
      EXPECT_TRUE(std::binary_search(members.begin(), members.end(), picks[static_cast<std::size_t>(c)]))
          << "pick " << c << " is not from cluster " << c;
    }
  }
}

TEST(DiverseSelectionTest, MedoidWorkedByHand) {
  // Points on a line at 0, 1, 3 (leaves 0..2) and far away at 100, 101 (leaves 3, 4).
  // k = 2: clusters {0,1,2} and {3,4}. Sums of distances in the first: 0 -> 4, 1 -> 3, 2 -> 5, so leaf 1;
  // in the second both sums are 1, and the tie goes to the lower index, leaf 3.
  // k = 1: sums over all five are 205, 202, 200, 297, 300, so leaf 2.
  const double x[] = {0, 1, 3, 100, 101};
  Eigen::MatrixXd d(5, 5);
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) d(i, j) = std::abs(x[i] - x[j]);
  }
  const Tree tree = upgma(d);
  EXPECT_EQ(cutIntoClusters(tree, 2), (std::vector<std::vector<int>>{{0, 1, 2}, {3, 4}}));
  EXPECT_EQ(selectDiverse(tree, d, 2), (std::vector<int>{1, 3}));
  EXPECT_EQ(selectDiverse(tree, d, 1), (std::vector<int>{2}));
  const std::vector<double> hardness{5, 2, 7, 1, 1};
  EXPECT_EQ(selectDiverse(tree, d, 2, &hardness), (std::vector<int>{2, 3}));
}

TEST(DiverseSelectionTest, PreferHardestPicksEachClustersMaximum) {
  Rng rng(77);
  const Eigen::MatrixXd d = randomDistances(rng, 50);
  const Tree tree = upgma(d);
  std::vector<double> hardness;
  for (int i = 0; i < 50; ++i) hardness.push_back(rng.uniform01() * 10);
  for (const int k : {1, 4, 9, 25}) {
    SCOPED_TRACE("k = " + std::to_string(k));
    const std::vector<int> picks = selectDiverse(tree, d, k, &hardness);
    const std::vector<std::vector<int>> clusters = cutIntoClusters(tree, k);
    ASSERT_EQ(picks.size(), static_cast<std::size_t>(k));
    for (int c = 0; c < k; ++c) {
      double best = -1;
      for (const int m : clusters[static_cast<std::size_t>(c)]) best = std::max(best, hardness[static_cast<std::size_t>(m)]);
      EXPECT_EQ(hardness[static_cast<std::size_t>(picks[static_cast<std::size_t>(c)])], best);
    }
  }
}

TEST(DiverseSelectionTest, RejectsBadArguments) {
  Rng rng(3);
  const Eigen::MatrixXd d = randomDistances(rng, 6);
  const Tree tree = upgma(d);
  const auto expectName = [&](const char* name, int k, const Eigen::MatrixXd& dist, const std::vector<double>* hard) {
    try {
      selectDiverse(tree, dist, k, hard);
      ADD_FAILURE() << "accepted bad " << name;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.name(), name);
    }
  };
  expectName("k", 0, d, nullptr);
  expectName("k", -3, d, nullptr);
  expectName("k", 7, d, nullptr);
  expectName("distances", 2, d.topLeftCorner(5, 5), nullptr);
  const std::vector<double> short_hardness{1, 2, 3};
  expectName("hardness", 2, d, &short_hardness);
  const std::vector<double> nan_hardness{1, 2, 3, 4, 5, std::numeric_limits<double>::quiet_NaN()};
  expectName("hardness", 2, d, &nan_hardness);
}

}  // namespace
}  // namespace ppp::generator
