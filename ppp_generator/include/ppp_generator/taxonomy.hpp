#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

#include "ppp_core/evaluation.hpp"

namespace ppp::generator {

/// Which taxonomic characters (docs/reference/evaluation.md) describe a PPP in the taxonomy.
enum class CharacterSet {
  Wei,       ///< Wei's four: turns, advances, turns_plus_advances, obstacles.
  Extended,  ///< All fourteen characters of ppp::characterNames().
  Barn,      ///< BARN's five metrics, ppp::barnCharacterNames(), measured on the PPPs' grids.
};

/// Parses "wei", "extended" or "barn". @throws InvalidArgument naming "characters" for any other name.
CharacterSet parseCharacterSet(const std::string& name);
/// The set's keyword ("wei", "extended" or "barn").
const char* characterSetName(CharacterSet set);
/// Names of the set's characters, in column order of characterMatrix() or barnCharacterMatrix().
std::vector<std::string> characterSetNames(CharacterSet set);
/// Every character a PPP can be described by (the archive's features): ppp::characterNames(), then
/// ppp::barnCharacterNames().
const std::vector<std::string>& availableCharacterNames();

/// One row per PPP, one column per character of the Wei or Extended set (raw values from ppp::characterVector()).
/// @throws InvalidArgument naming "evaluations" when a PPP is invalid (goal unreachable), "characters" for the
/// Barn set (measured on the grids: barnCharacterMatrix()).
Eigen::MatrixXd characterMatrix(const std::vector<ppp::Evaluation>& evaluations, CharacterSet set);

/// One row per PPP, one column per BARN metric (ppp::barnMetrics() with default options, along its DPA route).
/// @throws InvalidArgument naming "problems" when a PPP is invalid (goal unreachable).
Eigen::MatrixXd barnCharacterMatrix(const std::vector<ppp::Problem>& problems);

/// Min-max scales every column to [0, 1]; a constant column becomes all 0.
/// @throws InvalidArgument naming "characters" for a NaN or infinite value.
Eigen::MatrixXd normaliseColumns(const Eigen::MatrixXd& characters);

/// Symmetric matrix of Euclidean distances between the rows (zero diagonal).
/// @throws InvalidArgument naming "characters" for a NaN or infinite value.
Eigen::MatrixXd euclideanDistances(const Eigen::MatrixXd& characters);

/// The taxonomy's distances: Euclidean distances between the normalised character rows.
/// @throws InvalidArgument as characterMatrix().
Eigen::MatrixXd characterDistances(const std::vector<ppp::Evaluation>& evaluations, CharacterSet set);

/// One node of a binary tree; a leaf has no children.
struct TreeNode {
  int left = -1;      ///< Index of the first child (the one holding the smaller leaf index); -1 for a leaf.
  int right = -1;     ///< Index of the second child; -1 for a leaf.
  double height = 0;  ///< Half the UPGMA merge distance (ultrametric); 0 for a leaf.
  int size = 1;       ///< Leaves below this node, itself included.
};

/// A rooted binary tree: nodes 0..n-1 are the leaves in input order, n..2n-2 the merges in merge order
/// (every child's index is below its parent's, heights never decrease towards the root).
struct Tree {
  std::vector<TreeNode> nodes;  ///< Leaves first, then internal nodes in merge order.
  /// Index of the root (the last node); -1 for an empty tree.
  int root() const { return static_cast<int>(nodes.size()) - 1; }
  /// Number of leaves, (nodes + 1) / 2.
  int leafCount() const { return static_cast<int>((nodes.size() + 1) / 2); }
  /// True when node `index` has no children.
  bool isLeaf(int index) const { return nodes[static_cast<std::size_t>(index)].left < 0; }
};

/// Checks the layout documented on Tree (child indices, sizes, heights).
/// @throws InvalidArgument naming "tree" for an empty or inconsistent tree.
void validateTree(const Tree& tree);

/// UPGMA (size-weighted average linkage) over a distance matrix. Ties between equal distances go to the
/// pair whose (older, newer) cluster creation numbers are lowest (leaves are 0..n-1, merges n, n+1, ...).
/// @throws InvalidArgument naming "distances" for an empty, non-square, non-symmetric, negative,
/// non-finite or non-zero-diagonal matrix.
Tree upgma(const Eigen::MatrixXd& distances);

/// Undoes the k-1 last (highest) merges: k clusters of leaf indices, each sorted, ordered by smallest leaf.
/// @throws InvalidArgument naming "k" unless 1 <= k <= leafCount(), naming "tree" for a malformed tree.
std::vector<std::vector<int>> cutIntoClusters(const Tree& tree, int k);

/// Leaf indices in drawing order: a depth-first walk visiting `left` before `right`.
/// @throws InvalidArgument naming "tree" for a malformed tree.
std::vector<int> leafOrder(const Tree& tree);

}  // namespace ppp::generator
