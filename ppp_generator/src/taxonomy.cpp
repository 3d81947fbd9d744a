#include "ppp_generator/taxonomy.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "ppp_core/barn_metrics.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp::generator {

namespace {

std::string numberText(double value) { return formatGeneral(value, 15); }

std::string cellText(Eigen::Index row, Eigen::Index col) {
  return "(" + std::to_string(row) + ", " + std::to_string(col) + ")";
}

void requireFinite(const Eigen::MatrixXd& m, const std::string& name) {
  for (Eigen::Index c = 0; c < m.cols(); ++c) {
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
      if (!std::isfinite(m(r, c))) {
        throw InvalidArgument(name, "entry " + cellText(r, c) + " is " + numberText(m(r, c)) +
                                        ", expected a finite number");
      }
    }
  }
}

/// Checks a distance matrix and returns it exactly symmetric (mirrored pairs averaged).
Eigen::MatrixXd checkedDistances(const Eigen::MatrixXd& d) {
  if (d.rows() != d.cols()) {
    throw InvalidArgument("distances", "matrix is " + std::to_string(d.rows()) + " x " +
                                           std::to_string(d.cols()) + ", expected a square matrix");
  }
  if (d.rows() == 0) throw InvalidArgument("distances", "matrix is empty, expected at least one PPP");
  requireFinite(d, "distances");
  const Eigen::Index n = d.rows();
  Eigen::MatrixXd s(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    if (d(j, j) != 0) {
      throw InvalidArgument("distances", "diagonal entry " + cellText(j, j) + " is " + numberText(d(j, j)) +
                                             ", expected 0");
    }
    s(j, j) = 0;
    for (Eigen::Index i = j + 1; i < n; ++i) {
      const double a = d(i, j);
      const double b = d(j, i);
      if (a < 0) {
        throw InvalidArgument("distances", "entry " + cellText(i, j) + " is " + numberText(a) +
                                               ", expected a distance >= 0");
      }
      if (b < 0) {
        throw InvalidArgument("distances", "entry " + cellText(j, i) + " is " + numberText(b) +
                                               ", expected a distance >= 0");
      }
      if (std::abs(a - b) > 1e-12 * std::max(a, b)) {
        throw InvalidArgument("distances", "not symmetric: " + cellText(i, j) + " is " + numberText(a) +
                                               " but " + cellText(j, i) + " is " + numberText(b));
      }
      s(i, j) = s(j, i) = 0.5 * (a + b);
    }
  }
  return s;
}

/// The leaf indices below `top`, left to right (left subtree first).
std::vector<int> leavesLeftToRight(const Tree& tree, int top) {
  std::vector<int> leaves;
  std::vector<int> stack{top};
  while (!stack.empty()) {
    const int i = stack.back();
    stack.pop_back();
    const TreeNode& node = tree.nodes[static_cast<std::size_t>(i)];
    if (node.left < 0) {
      leaves.push_back(i);
    } else {
      stack.push_back(node.right);
      stack.push_back(node.left);
    }
  }
  return leaves;
}

/// The leaf indices below `top`, ascending.
std::vector<int> leavesBelow(const Tree& tree, int top) {
  std::vector<int> leaves = leavesLeftToRight(tree, top);
  std::sort(leaves.begin(), leaves.end());
  return leaves;
}

/// UPGMA working state: a shrinking distance matrix over "slots" (the live clusters packed into
/// 0..live-1) plus each slot's nearest neighbour, so a merge usually costs O(n) instead of O(n^2).
class Upgma {
 public:
  explicit Upgma(Eigen::MatrixXd distances)
      : d_(std::move(distances)),
        n_(static_cast<int>(d_.rows())),
        live_(n_),
        cluster_(static_cast<std::size_t>(n_)),
        size_(static_cast<std::size_t>(n_), 1),
        nearest_(static_cast<std::size_t>(n_), -1),
        nearest_distance_(static_cast<std::size_t>(n_), kInf),
        stale_(static_cast<std::size_t>(n_), 0) {
    d_.diagonal().setConstant(kInf);  // a slot is never its own neighbour
    tree_.nodes.resize(static_cast<std::size_t>(2 * n_ - 1));
    for (int s = 0; s < n_; ++s) cluster_[static_cast<std::size_t>(s)] = s;
    for (int s = 0; s < n_; ++s) findNearest(s);
  }

  Tree run() {
    while (live_ > 1) mergeClosestPair();
    return std::move(tree_);
  }

 private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();

  /// True when pair (a, b) at distance da beats pair (c, e) at distance dc: smaller distance, then the
  /// lower (older, newer) creation numbers.
  bool pairBeats(double da, int a, int b, double dc, int c, int e) const {
    if (da != dc) return da < dc;
    const int ca = cluster_[static_cast<std::size_t>(a)], cb = cluster_[static_cast<std::size_t>(b)];
    const int cc = cluster_[static_cast<std::size_t>(c)], ce = cluster_[static_cast<std::size_t>(e)];
    return std::make_pair(std::min(ca, cb), std::max(ca, cb)) < std::make_pair(std::min(cc, ce), std::max(cc, ce));
  }

  /// Finds row s's best partner. For a fixed s the lowest (older, newer) pair is the one with the oldest
  /// partner, so ties within a row go to the smallest creation number.
  void findNearest(int s) {
    if (live_ < 2) return;
    const double* column = d_.col(s).data();  // column s == row s; columns are contiguous
    const int* cluster = cluster_.data();
    double best = kInf;
    int best_slot = -1;
    int best_cluster = std::numeric_limits<int>::max();
    for (int t = 0; t < live_; ++t) {
      const double v = column[t];  // inf on the diagonal, so t == s only wins if nothing else does
      if (v < best || (v == best && cluster[t] < best_cluster)) {
        best = v;
        best_slot = t;
        best_cluster = cluster[t];
      }
    }
    nearest_[static_cast<std::size_t>(s)] = best_slot;
    nearest_distance_[static_cast<std::size_t>(s)] = best;
  }

  void mergeClosestPair() {
    int a = 0;
    for (int s = 1; s < live_; ++s) {
      const std::size_t us = static_cast<std::size_t>(s), ua = static_cast<std::size_t>(a);
      if (pairBeats(nearest_distance_[us], s, nearest_[us], nearest_distance_[ua], a, nearest_[ua])) a = s;
    }
    int b = nearest_[static_cast<std::size_t>(a)];
    const double distance = nearest_distance_[static_cast<std::size_t>(a)];
    if (b < a) std::swap(a, b);  // the merged cluster takes the lower slot; the higher one is freed

    const int merged = recordMerge(a, b, distance);

    for (int s = 0; s < live_; ++s) {
      const int nearest = nearest_[static_cast<std::size_t>(s)];
      stale_[static_cast<std::size_t>(s)] = (nearest == a || nearest == b) ? 1 : 0;
    }
    const double wa = size_[static_cast<std::size_t>(a)], wb = size_[static_cast<std::size_t>(b)];
    for (int s = 0; s < live_; ++s) {
      if (s == a || s == b) continue;
      const double v = (wa * d_(s, a) + wb * d_(s, b)) / (wa + wb);
      d_(s, a) = v;
      d_(a, s) = v;
    }
    size_[static_cast<std::size_t>(a)] += size_[static_cast<std::size_t>(b)];
    cluster_[static_cast<std::size_t>(a)] = merged;
    removeSlot(b);

    for (int s = 0; s < live_; ++s) {
      const std::size_t us = static_cast<std::size_t>(s);
      if (s == a || stale_[us]) {
        findNearest(s);
      } else {
        const double v = d_(s, a);
        if (v < nearest_distance_[us] ||
            (v == nearest_distance_[us] && merged < cluster_[static_cast<std::size_t>(nearest_[us])])) {
          nearest_[us] = a;
          nearest_distance_[us] = v;
        }
      }
    }
  }

  /// Adds the node joining the clusters in slots a and b; returns its index.
  int recordMerge(int a, int b, double distance) {
    const int index = 2 * n_ - live_;  // n, n+1, ... in merge order
    const int ca = cluster_[static_cast<std::size_t>(a)], cb = cluster_[static_cast<std::size_t>(b)];
    const int first_a = smallestLeaf(ca), first_b = smallestLeaf(cb);
    TreeNode& node = tree_.nodes[static_cast<std::size_t>(index)];
    node.left = first_a < first_b ? ca : cb;
    node.right = first_a < first_b ? cb : ca;
    const TreeNode& l = tree_.nodes[static_cast<std::size_t>(node.left)];
    const TreeNode& r = tree_.nodes[static_cast<std::size_t>(node.right)];
    // max() guards the ultrametric order against rounding in the averaged distances.
    node.height = std::max({distance / 2, l.height, r.height});
    node.size = l.size + r.size;
    smallest_leaf_.push_back(std::min(first_a, first_b));
    return index;
  }

  int smallestLeaf(int node) const {
    return node < n_ ? node : smallest_leaf_[static_cast<std::size_t>(node - n_)];
  }

  /// Frees slot `b` by moving the last live slot into it.
  void removeSlot(int b) {
    const int last = live_ - 1;
    if (b != last) {
      d_.col(b).head(live_) = d_.col(last).head(live_);
      d_(b, b) = kInf;
      d_(last, b) = kInf;
      d_.row(b).head(live_) = d_.col(b).head(live_).transpose();
      const std::size_t ub = static_cast<std::size_t>(b), ul = static_cast<std::size_t>(last);
      cluster_[ub] = cluster_[ul];
      size_[ub] = size_[ul];
      nearest_[ub] = nearest_[ul];
      nearest_distance_[ub] = nearest_distance_[ul];
      stale_[ub] = stale_[ul];
      for (int s = 0; s < last; ++s) {
        if (nearest_[static_cast<std::size_t>(s)] == last) nearest_[static_cast<std::size_t>(s)] = b;
      }
    }
    live_ = last;
  }

  Eigen::MatrixXd d_;
  int n_;
  int live_;
  std::vector<int> cluster_;  // node index held by each slot
  std::vector<int> size_;
  std::vector<int> nearest_;
  std::vector<double> nearest_distance_;
  std::vector<char> stale_;
  std::vector<int> smallest_leaf_;  // per internal node
  Tree tree_;
};

}  // namespace

CharacterSet parseCharacterSet(const std::string& name) {
  if (name == "wei") return CharacterSet::Wei;
  if (name == "extended") return CharacterSet::Extended;
  if (name == "barn") return CharacterSet::Barn;
  throw InvalidArgument("characters", "unknown character set '" + name + "'; valid: wei, extended, barn");
}

const char* characterSetName(CharacterSet set) {
  if (set == CharacterSet::Wei) return "wei";
  return set == CharacterSet::Extended ? "extended" : "barn";
}

std::vector<std::string> characterSetNames(CharacterSet set) {
  const std::vector<std::string>& all = ppp::characterNames();
  if (set == CharacterSet::Extended) return all;
  if (set == CharacterSet::Barn) return ppp::barnCharacterNames();
  return std::vector<std::string>(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(kWeiCharacterCount));
}

const std::vector<std::string>& availableCharacterNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all = ppp::characterNames();
    all.insert(all.end(), ppp::barnCharacterNames().begin(), ppp::barnCharacterNames().end());
    return all;
  }();
  return names;
}

Eigen::MatrixXd characterMatrix(const std::vector<ppp::Evaluation>& evaluations, CharacterSet set) {
  if (set == CharacterSet::Barn) {
    throw InvalidArgument("characters", "the barn characters are measured on the grids: use barnCharacterMatrix");
  }
  const std::size_t columns = characterSetNames(set).size();
  Eigen::MatrixXd m(static_cast<Eigen::Index>(evaluations.size()), static_cast<Eigen::Index>(columns));
  for (std::size_t r = 0; r < evaluations.size(); ++r) {
    if (!evaluations[r].valid) {
      throw InvalidArgument("evaluations", "PPP " + std::to_string(r) +
                                               " is invalid (goal unreachable); only solvable PPPs have characters");
    }
    const std::vector<double> v = ppp::characterVector(evaluations[r]);
    for (std::size_t c = 0; c < columns; ++c) {
      m(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = v[c];
    }
  }
  return m;
}

Eigen::MatrixXd barnCharacterMatrix(const std::vector<ppp::Problem>& problems) {
  Eigen::MatrixXd m(static_cast<Eigen::Index>(problems.size()),
                    static_cast<Eigen::Index>(ppp::barnCharacterNames().size()));
  for (std::size_t r = 0; r < problems.size(); ++r) {
    const ppp::BarnMetrics metrics = ppp::barnMetrics(problems[r], decodeGrid(problems[r]));
    if (!metrics.valid) {
      throw InvalidArgument("problems", "PPP " + std::to_string(r) + " is invalid (goal unreachable); only solvable "
                                        "PPPs have characters");
    }
    const std::vector<double> v = ppp::barnCharacterVector(metrics);
    for (std::size_t c = 0; c < v.size(); ++c) m(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = v[c];
  }
  return m;
}

Eigen::MatrixXd normaliseColumns(const Eigen::MatrixXd& characters) {
  requireFinite(characters, "characters");
  Eigen::MatrixXd out(characters.rows(), characters.cols());
  for (Eigen::Index c = 0; c < characters.cols(); ++c) {
    if (characters.rows() == 0) break;
    const double lo = characters.col(c).minCoeff();
    const double range = characters.col(c).maxCoeff() - lo;
    if (range > 0) {
      out.col(c) = (characters.col(c).array() - lo) / range;
    } else {
      out.col(c).setZero();
    }
  }
  return out;
}

Eigen::MatrixXd euclideanDistances(const Eigen::MatrixXd& characters) {
  requireFinite(characters, "characters");
  const Eigen::MatrixXd points = characters.transpose();  // one contiguous column per PPP
  const Eigen::Index n = points.cols();
  Eigen::MatrixXd d(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    d(j, j) = 0;
    for (Eigen::Index i = j + 1; i < n; ++i) d(i, j) = d(j, i) = (points.col(i) - points.col(j)).norm();
  }
  return d;
}

Eigen::MatrixXd characterDistances(const std::vector<ppp::Evaluation>& evaluations, CharacterSet set) {
  return euclideanDistances(normaliseColumns(characterMatrix(evaluations, set)));
}

void validateTree(const Tree& tree) {
  const int count = static_cast<int>(tree.nodes.size());
  if (count == 0) throw InvalidArgument("tree", "tree is empty, expected at least one leaf");
  if (count % 2 == 0) {
    throw InvalidArgument("tree", std::to_string(count) + " nodes, expected 2n-1 for a binary tree of n leaves");
  }
  const int n = tree.leafCount();
  std::vector<char> used(static_cast<std::size_t>(count), 0);
  for (int i = 0; i < count; ++i) {
    const TreeNode& node = tree.nodes[static_cast<std::size_t>(i)];
    const std::string where = "node " + std::to_string(i);
    if (!std::isfinite(node.height)) throw InvalidArgument("tree", where + " has a non-finite height");
    if (i < n) {
      if (node.left != -1 || node.right != -1 || node.size != 1 || node.height != 0) {
        throw InvalidArgument("tree", where + " should be a leaf (no children, size 1, height 0)");
      }
      continue;
    }
    for (const int child : {node.left, node.right}) {
      if (child < 0 || child >= i || used[static_cast<std::size_t>(child)]) {
        throw InvalidArgument("tree", where + " has child " + std::to_string(child) +
                                          ", expected an unused node with a lower index");
      }
      used[static_cast<std::size_t>(child)] = 1;
      if (tree.nodes[static_cast<std::size_t>(child)].height > node.height) {
        throw InvalidArgument("tree", where + " is lower than its child " + std::to_string(child));
      }
    }
    if (node.left == node.right ||
        node.size != tree.nodes[static_cast<std::size_t>(node.left)].size +
                         tree.nodes[static_cast<std::size_t>(node.right)].size) {
      throw InvalidArgument("tree", where + " has size " + std::to_string(node.size) +
                                        ", expected the sum of its children's");
    }
  }
}

Tree upgma(const Eigen::MatrixXd& distances) { return Upgma(checkedDistances(distances)).run(); }

std::vector<std::vector<int>> cutIntoClusters(const Tree& tree, int k) {
  validateTree(tree);
  const int n = tree.leafCount();
  if (k < 1) throw InvalidArgument("k", "asked for " + std::to_string(k) + " clusters, expected at least 1");
  if (k > n) {
    throw InvalidArgument("k", "asked for " + std::to_string(k) + " clusters, larger than the set of " +
                                   std::to_string(n) + " PPPs");
  }
  const int first_undone = 2 * n - k;  // internal nodes [first_undone, 2n-1) are split
  std::vector<int> tops;
  if (k == 1) tops.push_back(tree.root());
  for (int i = first_undone; i < 2 * n - 1; ++i) {
    for (const int child : {tree.nodes[static_cast<std::size_t>(i)].left, tree.nodes[static_cast<std::size_t>(i)].right}) {
      if (child < first_undone) tops.push_back(child);
    }
  }
  std::vector<std::vector<int>> clusters;
  clusters.reserve(tops.size());
  for (const int top : tops) clusters.push_back(leavesBelow(tree, top));
  std::sort(clusters.begin(), clusters.end(),
            [](const std::vector<int>& x, const std::vector<int>& y) { return x.front() < y.front(); });
  return clusters;
}

std::vector<int> leafOrder(const Tree& tree) {
  validateTree(tree);
  return leavesLeftToRight(tree, tree.root());
}

}  // namespace ppp::generator
