// libFuzzer target for the Newick reader: parseNewick must either return a tree or throw ppp::Error; a tree it
// returns must survive toNewick -> parseNewick with the same labels, the same shape (the same clusters of
// leaves) and its heights to the precision of the written lengths (10 significant digits, summed along the path
// from the leaves). Internal nodes are numbered by height, so two of nearly equal height may swap numbers in
// a round trip: the shape is compared by cluster, not by node number.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/fuzz_finding.hpp"
#include "ppp_generator/newick.hpp"

namespace {

/// Each internal node's cluster (its leaves, in leaf order) with the node's height.
std::map<std::vector<int>, double> clusters(const ppp::generator::Tree& tree) {
  std::vector<std::vector<int>> leaves_of(tree.nodes.size());
  std::map<std::vector<int>, double> result;
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) {  // children come before their parents
    const ppp::generator::TreeNode& node = tree.nodes[i];
    if (node.left < 0) {
      leaves_of[i] = {static_cast<int>(i)};
      continue;
    }
    std::vector<int>& mine = leaves_of[i];
    const std::vector<int>& left = leaves_of[static_cast<std::size_t>(node.left)];
    const std::vector<int>& right = leaves_of[static_cast<std::size_t>(node.right)];
    mine.resize(left.size() + right.size());
    std::merge(left.begin(), left.end(), right.begin(), right.end(), mine.begin());
    result[mine] = node.height;
  }
  return result;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using ppp::fuzz::finding;
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> labels;
  ppp::generator::Tree tree;
  try {
    tree = ppp::generator::parseNewick(text, &labels);
  } catch (const ppp::Error&) {
    return 0;
  }
  std::string written;
  try {
    written = ppp::generator::toNewick(tree, labels);
  } catch (const ppp::Error& e) {
    finding("newick_fuzz", "toNewick refuses a tree parseNewick returned", e.what());
  }
  std::vector<std::string> labels_again;
  try {
    const ppp::generator::Tree again = ppp::generator::parseNewick(written, &labels_again);
    if (labels_again != labels) finding("newick_fuzz", "labels changed in a round trip", written);
    if (again.nodes.size() != tree.nodes.size()) finding("newick_fuzz", "node count changed", written);
    const std::map<std::vector<int>, double> before = clusters(tree);
    const std::map<std::vector<int>, double> after = clusters(again);
    if (before.size() != after.size()) finding("newick_fuzz", "the clusters changed in a round trip", written);
    for (auto a = before.begin(), b = after.begin(); a != before.end(); ++a, ++b) {
      const double tolerance = 1e-6 * (1.0 + std::fabs(a->second)) * static_cast<double>(tree.nodes.size());
      if (a->first != b->first || std::fabs(a->second - b->second) > tolerance) {
        finding("newick_fuzz", "the tree changed in a round trip", written);
      }
    }
  } catch (const ppp::Error& e) {
    finding("newick_fuzz", "parseNewick rejects toNewick's output", written + "\n" + e.what());
  }
  return 0;
}
