#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "ppp_generator/taxonomy.hpp"

namespace ppp::generator {

/// The tree as nested JSON objects: a leaf is {"name", "index", "height": 0}, an internal node
/// {"height", "size", "children": [left, right]}.
/// @throws InvalidArgument naming "tree" for a malformed tree, "labels" unless there is one per leaf.
nlohmann::json treeToJson(const Tree& tree, const std::vector<std::string>& labels);

}  // namespace ppp::generator
