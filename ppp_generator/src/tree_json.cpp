#include "ppp_generator/tree_json.hpp"

#include <string>
#include <utility>
#include <vector>

#include "ppp_core/error.hpp"

namespace ppp::generator {

nlohmann::json treeToJson(const Tree& tree, const std::vector<std::string>& labels) {
  validateTree(tree);
  if (labels.size() != static_cast<std::size_t>(tree.leafCount())) {
    throw InvalidArgument("labels", std::to_string(labels.size()) + " labels for " +
                                        std::to_string(tree.leafCount()) + " leaves, expected one per leaf");
  }
  // Children always precede their parent, so one pass builds every subtree before it is needed.
  std::vector<nlohmann::json> built(tree.nodes.size());
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
    const TreeNode& node = tree.nodes[i];
    if (node.left < 0) {
      built[i] = {{"name", labels[i]}, {"index", i}, {"height", 0.0}};
    } else {
      nlohmann::json children = nlohmann::json::array();
      children.push_back(std::move(built[static_cast<std::size_t>(node.left)]));
      children.push_back(std::move(built[static_cast<std::size_t>(node.right)]));
      built[i] = {{"height", node.height}, {"size", node.size}, {"children", std::move(children)}};
    }
  }
  return std::move(built.back());
}

}  // namespace ppp::generator
