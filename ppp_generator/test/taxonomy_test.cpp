#include "ppp_generator/taxonomy.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ppp_core/barn_metrics.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/rng.hpp"
#include "hand_tree.hpp"

namespace ppp::generator {
namespace {

using test::handDistances;

void expectNode(const Tree& tree, int index, int left, int right, double height, int size) {
  SCOPED_TRACE("node " + std::to_string(index));
  const TreeNode& node = tree.nodes[static_cast<std::size_t>(index)];
  EXPECT_EQ(node.left, left);
  EXPECT_EQ(node.right, right);
  EXPECT_DOUBLE_EQ(node.height, height);
  EXPECT_EQ(node.size, size);
}

Eigen::MatrixXd randomMatrix(Rng& rng, int rows, int cols, double scale) {
  Eigen::MatrixXd m(rows, cols);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) m(r, c) = (rng.uniform01() - 0.5) * scale;
  }
  return m;
}

TEST(TaxonomyTest, UpgmaWorkedByHand) {
  const Tree tree = upgma(handDistances());
  ASSERT_EQ(tree.nodes.size(), 9u);
  EXPECT_EQ(tree.leafCount(), 5);
  EXPECT_EQ(tree.root(), 8);
  for (int leaf = 0; leaf < 5; ++leaf) expectNode(tree, leaf, -1, -1, 0, 1);
  expectNode(tree, 5, 0, 1, 8.5, 2);
  expectNode(tree, 6, 5, 4, 11, 3);
  expectNode(tree, 7, 2, 3, 14, 2);
  expectNode(tree, 8, 6, 7, 16.5, 5);
  EXPECT_EQ(leafOrder(tree), (std::vector<int>{0, 1, 4, 2, 3}));
}

TEST(TaxonomyTest, UpgmaDoesNotDependOnInputOrderBeyondLabels) {
  // The hand matrix with the taxa reversed (e, d, c, b, a): same clades, same heights.
  const Eigen::MatrixXd d = handDistances();
  Eigen::MatrixXd reversed(5, 5);
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) reversed(i, j) = d(4 - i, 4 - j);
  }
  const Tree tree = upgma(reversed);
  expectNode(tree, 5, 3, 4, 8.5, 2);    // (b, a)
  expectNode(tree, 6, 0, 5, 11, 3);     // (e, (b, a)): e holds leaf 0, so it comes first
  expectNode(tree, 7, 1, 2, 14, 2);     // (d, c)
  expectNode(tree, 8, 6, 7, 16.5, 5);
}

TEST(TaxonomyTest, TiesGoToTheOldestPair) {
  // Four points all at distance 1: (0,1) first; then (2,3), (2,4), (3,4) tie at 1 and (2,3) is the oldest pair.
  Eigen::MatrixXd d = Eigen::MatrixXd::Ones(4, 4);
  d.diagonal().setZero();
  const Tree tree = upgma(d);
  expectNode(tree, 4, 0, 1, 0.5, 2);
  expectNode(tree, 5, 2, 3, 0.5, 2);
  expectNode(tree, 6, 4, 5, 0.5, 4);
}

TEST(TaxonomyTest, OneAndTwoLeaves) {
  const Tree one = upgma(Eigen::MatrixXd::Zero(1, 1));
  ASSERT_EQ(one.nodes.size(), 1u);
  EXPECT_EQ(one.root(), 0);
  EXPECT_EQ(one.leafCount(), 1);
  EXPECT_EQ(cutIntoClusters(one, 1), (std::vector<std::vector<int>>{{0}}));

  Eigen::MatrixXd d(2, 2);
  d << 0, 3, 3, 0;
  const Tree two = upgma(d);
  ASSERT_EQ(two.nodes.size(), 3u);
  expectNode(two, 2, 0, 1, 1.5, 2);
}

TEST(TaxonomyTest, UpgmaOnRandomPointsIsAValidUltrametricTree) {
  Rng rng(11);
  for (const int n : {3, 17, 64}) {
    const Eigen::MatrixXd d = euclideanDistances(randomMatrix(rng, n, 5, 2.0));
    const Tree tree = upgma(d);
    EXPECT_NO_THROW(validateTree(tree));
    EXPECT_EQ(tree.leafCount(), n);
    EXPECT_EQ(tree.nodes.back().size, n);
    for (std::size_t i = static_cast<std::size_t>(n) + 1; i < tree.nodes.size(); ++i) {
      EXPECT_GE(tree.nodes[i].height, tree.nodes[i - 1].height) << "merge heights never decrease";
    }
  }
}

/// Textbook UPGMA, O(n^3): every step scans all pairs of live clusters in creation order.
Tree naiveUpgma(const Eigen::MatrixXd& d0) {
  const int n = static_cast<int>(d0.rows());
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(2 * n - 1, 2 * n - 1);
  d.topLeftCorner(n, n) = d0;
  Tree tree;
  tree.nodes.resize(static_cast<std::size_t>(2 * n - 1));
  std::vector<int> live(static_cast<std::size_t>(n));
  std::vector<int> smallest(static_cast<std::size_t>(2 * n - 1));
  for (int i = 0; i < n; ++i) live[static_cast<std::size_t>(i)] = smallest[static_cast<std::size_t>(i)] = i;
  for (int c = n; c < 2 * n - 1; ++c) {
    std::size_t bi = 0, bj = 1;
    for (std::size_t i = 0; i < live.size(); ++i) {
      for (std::size_t j = i + 1; j < live.size(); ++j) {
        if (d(live[i], live[j]) < d(live[bi], live[bj])) bi = i, bj = j;
      }
    }
    const int a = live[bi], b = live[bj];
    TreeNode& node = tree.nodes[static_cast<std::size_t>(c)];
    const bool a_first = smallest[static_cast<std::size_t>(a)] < smallest[static_cast<std::size_t>(b)];
    node.left = a_first ? a : b;
    node.right = a_first ? b : a;
    const TreeNode& na = tree.nodes[static_cast<std::size_t>(a)];
    const TreeNode& nb = tree.nodes[static_cast<std::size_t>(b)];
    node.height = std::max({d(a, b) / 2, na.height, nb.height});
    node.size = na.size + nb.size;
    smallest[static_cast<std::size_t>(c)] = std::min(smallest[static_cast<std::size_t>(a)], smallest[static_cast<std::size_t>(b)]);
    live.erase(live.begin() + static_cast<std::ptrdiff_t>(bj));
    live.erase(live.begin() + static_cast<std::ptrdiff_t>(bi));
    for (const int k : live) {
      d(c, k) = d(k, c) = (na.size * d(a, k) + nb.size * d(b, k)) / (na.size + nb.size);
    }
    live.push_back(c);
  }
  return tree;
}

TEST(TaxonomyTest, UpgmaMatchesTheTextbookAlgorithmIncludingTies) {
  Rng rng(42);
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 2 + static_cast<int>(rng.below(40));
    const bool ties = trial % 2 == 0;  // small integer distances: many equal pairs
    Eigen::MatrixXd d = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        d(i, j) = d(j, i) = ties ? static_cast<double>(1 + rng.below(4)) : rng.uniform01();
      }
    }
    SCOPED_TRACE("trial " + std::to_string(trial) + ", n = " + std::to_string(n));
    const Tree fast = upgma(d);
    const Tree slow = naiveUpgma(d);
    ASSERT_EQ(fast.nodes.size(), slow.nodes.size());
    for (std::size_t i = 0; i < slow.nodes.size(); ++i) {
      const TreeNode& s = slow.nodes[i];
      expectNode(fast, static_cast<int>(i), s.left, s.right, s.height, s.size);
    }
  }
}

TEST(TaxonomyTest, BadDistanceMatricesThrow) {
  const auto expectRejected = [](const Eigen::MatrixXd& d) {
    try {
      upgma(d);
      ADD_FAILURE() << "accepted\n" << d;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.name(), "distances");
    }
  };
  expectRejected(Eigen::MatrixXd(0, 0));
  expectRejected(Eigen::MatrixXd::Zero(2, 3));
  Eigen::MatrixXd d = handDistances();
  d(0, 1) = 18;
  expectRejected(d);  // not symmetric
  d = handDistances();
  d(2, 3) = d(3, 2) = -1;
  expectRejected(d);
  d = handDistances();
  d(1, 4) = d(4, 1) = std::numeric_limits<double>::quiet_NaN();
  expectRejected(d);
  d = handDistances();
  d(1, 4) = d(4, 1) = std::numeric_limits<double>::infinity();
  expectRejected(d);
  d = handDistances();
  d(2, 2) = 1;
  expectRejected(d);
}

TEST(TaxonomyTest, CutHandTreeIntoOneToFiveClusters) {
  const Tree tree = upgma(handDistances());
  using Clusters = std::vector<std::vector<int>>;
  EXPECT_EQ(cutIntoClusters(tree, 1), (Clusters{{0, 1, 2, 3, 4}}));
  EXPECT_EQ(cutIntoClusters(tree, 2), (Clusters{{0, 1, 4}, {2, 3}}));
  EXPECT_EQ(cutIntoClusters(tree, 3), (Clusters{{0, 1, 4}, {2}, {3}}));
  EXPECT_EQ(cutIntoClusters(tree, 4), (Clusters{{0, 1}, {2}, {3}, {4}}));
  EXPECT_EQ(cutIntoClusters(tree, 5), (Clusters{{0}, {1}, {2}, {3}, {4}}));
}

TEST(TaxonomyTest, CutRejectsImpossibleK) {
  const Tree tree = upgma(handDistances());
  for (const int k : {0, -1, 6}) {
    try {
      cutIntoClusters(tree, k);
      ADD_FAILURE() << "accepted k = " << k;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.name(), "k");
      if (k == 6) {
        EXPECT_NE(std::string(e.what()).find("larger than the set of 5 PPPs"), std::string::npos) << e.what();
      }
    }
  }
}

TEST(TaxonomyTest, MalformedTreesAreRejected) {
  Tree tree = upgma(handDistances());
  tree.nodes[8].left = 8;
  EXPECT_THROW(cutIntoClusters(tree, 2), InvalidArgument);
  tree = upgma(handDistances());
  tree.nodes[6].right = 0;  // leaf 0 twice
  EXPECT_THROW(validateTree(tree), InvalidArgument);
  tree = upgma(handDistances());
  tree.nodes[8].height = 1;  // below its children
  EXPECT_THROW(validateTree(tree), InvalidArgument);
  EXPECT_THROW(validateTree(Tree{}), InvalidArgument);
}

TEST(TaxonomyTest, NormalisedColumnsStayInUnitRangeAndConstantsBecomeZero) {
  Rng rng(5);
  Eigen::MatrixXd m = randomMatrix(rng, 50, 6, 100.0);
  m.col(2).setConstant(7.25);
  const Eigen::MatrixXd z = normaliseColumns(m);
  ASSERT_EQ(z.rows(), 50);
  ASSERT_EQ(z.cols(), 6);
  EXPECT_GE(z.minCoeff(), 0.0);
  EXPECT_LE(z.maxCoeff(), 1.0);
  EXPECT_TRUE(z.col(2).isZero(0.0));
  for (const int c : {0, 1, 3, 4, 5}) {
    EXPECT_EQ(z.col(c).minCoeff(), 0.0);
    EXPECT_EQ(z.col(c).maxCoeff(), 1.0);
    Eigen::Index lo = 0;
    m.col(c).minCoeff(&lo);
    EXPECT_EQ(z(lo, c), 0.0);
  }
  Eigen::MatrixXd bad = m;
  bad(3, 3) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(normaliseColumns(bad), InvalidArgument);
}

TEST(TaxonomyTest, DistancesAreSymmetricWithZeroDiagonal) {
  Rng rng(9);
  const Eigen::MatrixXd points = randomMatrix(rng, 30, 14, 1.0);
  const Eigen::MatrixXd d = euclideanDistances(points);
  ASSERT_EQ(d.rows(), 30);
  ASSERT_EQ(d.cols(), 30);
  EXPECT_TRUE(d.isApprox(d.transpose(), 0.0));
  EXPECT_TRUE(d.diagonal().isZero(0.0));
  EXPECT_GE(d.minCoeff(), 0.0);
  EXPECT_DOUBLE_EQ(d(3, 17), (points.row(3) - points.row(17)).norm());

  Eigen::MatrixXd pythagoras(2, 2);
  pythagoras << 0, 0, 3, 4;
  EXPECT_DOUBLE_EQ(euclideanDistances(pythagoras)(0, 1), 5.0);
}

TEST(TaxonomyTest, CharacterSets) {
  EXPECT_EQ(parseCharacterSet("wei"), CharacterSet::Wei);
  EXPECT_EQ(parseCharacterSet("extended"), CharacterSet::Extended);
  EXPECT_STREQ(characterSetName(CharacterSet::Wei), "wei");
  EXPECT_STREQ(characterSetName(CharacterSet::Extended), "extended");
  EXPECT_EQ(characterSetNames(CharacterSet::Wei),
            (std::vector<std::string>{"turns", "advances", "turns_plus_advances", "obstacles"}));
  EXPECT_EQ(characterSetNames(CharacterSet::Extended), ppp::characterNames());
  EXPECT_EQ(characterSetNames(CharacterSet::Extended).size(), 14u);
  for (const char* bad : {"", "Wei", "all", "extended ", "BARN"}) {
    try {
      parseCharacterSet(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.name(), "characters");
      EXPECT_EQ(std::string(e.what()),
                std::string("characters: unknown character set '") + bad + "'; valid: wei, extended, barn");
    }
  }
}

TEST(TaxonomyTest, CharacterMatrixHasOneRowPerPpp) {
  Evaluation a;
  a.valid = true;
  a.turns = 2;
  a.advances = 10;
  a.turns_plus_advances = 12;
  a.obstacles = 3;
  a.difficulty = 9.5;
  Evaluation b = a;
  b.turns = 1;
  b.obstacles = 5;
  const Eigen::MatrixXd wei = characterMatrix({a, b}, CharacterSet::Wei);
  ASSERT_EQ(wei.rows(), 2);
  ASSERT_EQ(wei.cols(), 4);
  EXPECT_EQ(wei(0, 0), 2);
  EXPECT_EQ(wei(1, 3), 5);
  const Eigen::MatrixXd extended = characterMatrix({a, b}, CharacterSet::Extended);
  ASSERT_EQ(extended.cols(), 14);
  const std::vector<double> expected = characterVector(b);
  for (int c = 0; c < 14; ++c) EXPECT_EQ(extended(1, c), expected[static_cast<std::size_t>(c)]);

  // Wei: only turns (2 vs 1) and obstacles (3 vs 5) differ, each normalised to a full 0..1 step.
  const Eigen::MatrixXd d = characterDistances({a, b}, CharacterSet::Wei);
  EXPECT_DOUBLE_EQ(d(0, 1), std::sqrt(2.0));

  Evaluation invalid;
  try {
    characterMatrix({a, invalid}, CharacterSet::Wei);
    ADD_FAILURE() << "accepted an invalid PPP";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "evaluations");
  }
}

/// The PPP of the hand-worked corridor of barn_metrics_test: 5x3, walls above and below row 1, start (0,1), goal (4,1).
Problem corridorProblem() {
  Grid grid(5, 3);
  for (int x = 0; x < 5; ++x) {
    grid.setObstacle(Cell{x, 0}, true);
    grid.setObstacle(Cell{x, 2}, true);
  }
  return problemFromGrid(grid, Cell{0, 1}, Cell{4, 1});
}

TEST(TaxonomyTest, BarnCharactersCanBeSelected) {
  EXPECT_EQ(parseCharacterSet("barn"), CharacterSet::Barn);
  EXPECT_STREQ(characterSetName(CharacterSet::Barn), "barn");
  EXPECT_EQ(characterSetNames(CharacterSet::Barn), ppp::barnCharacterNames());
  // The archive's features: the fourteen, then BARN's five; the default sets keep their characters.
  const std::vector<std::string>& available = availableCharacterNames();
  ASSERT_EQ(available.size(), 19u);
  EXPECT_EQ(std::vector<std::string>(available.begin(), available.begin() + 14), ppp::characterNames());
  EXPECT_EQ(available[14], "barn_closest_obstacle");
  EXPECT_EQ(available[18], "barn_tortuosity");
  EXPECT_EQ(characterSetNames(CharacterSet::Extended).size(), 14u);

  Problem open = Problem::empty(5, 5, 0);
  const std::vector<Problem> problems{corridorProblem(), open};
  const Eigen::MatrixXd barn = barnCharacterMatrix(problems);
  ASSERT_EQ(barn.rows(), 2);
  ASSERT_EQ(barn.cols(), 5);
  // The corridor's metrics worked by hand in barn_metrics_test: clearance 0.5, visibility 0.75 + 0.25*sqrt2,
  // dispersion 1.6, characteristic dimension 1 (its width), tortuosity 1.
  const double expected[] = {0.5, 0.75 + 0.25 * std::sqrt(2.0), 1.6, 1.0, 1.0};
  for (int c = 0; c < 5; ++c) EXPECT_NEAR(barn(0, c), expected[c], 1e-12) << "column " << c;
  const std::vector<double> second = ppp::barnCharacterVector(ppp::barnMetrics(open, decodeGrid(open)));
  for (int c = 0; c < 5; ++c) EXPECT_EQ(barn(1, c), second[static_cast<std::size_t>(c)]);

  Problem walled = Problem::empty(4, 4, 1);
  walled.obstacles.push_back(Obstacle{Shape::VerticalBar, 2, 0, 4, 1});
  try {
    barnCharacterMatrix({open, walled});
    ADD_FAILURE() << "accepted an invalid PPP";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "problems");
  }
  try {
    characterMatrix({Evaluation{}}, CharacterSet::Barn);
    ADD_FAILURE() << "took the barn characters from evaluations";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "characters");
  }
}

}  // namespace
}  // namespace ppp::generator
