// libFuzzer target for the Newick reader: parseNewick must either return a tree or throw ppp::Error; a tree it
// returns must survive toNewick -> parseNewick with the same labels, the same shape and its heights to the
// precision of the written lengths (10 significant digits, summed along the path from the leaves).

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/fuzz_finding.hpp"
#include "ppp_generator/newick.hpp"

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
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
      const ppp::generator::TreeNode& a = tree.nodes[i];
      const ppp::generator::TreeNode& b = again.nodes[i];
      const double tolerance = 1e-6 * (1.0 + std::fabs(a.height)) * static_cast<double>(tree.nodes.size());
      if (a.left != b.left || a.right != b.right || a.size != b.size || std::fabs(a.height - b.height) > tolerance) {
        finding("newick_fuzz", "the tree changed in a round trip", written);
      }
    }
  } catch (const ppp::Error& e) {
    finding("newick_fuzz", "parseNewick rejects toNewick's output", written + "\n" + e.what());
  }
  return 0;
}
