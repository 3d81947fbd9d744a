#pragma once

#include <string>
#include <vector>

#include "ppp_generator/taxonomy.hpp"

namespace ppp::generator {

/// The tree in Newick, e.g. "((a:0.5,b:0.5):1.25,c:1.75);": branch length = parent height - child height
/// (10 significant digits), no length on the root, labels in single quotes when they hold a blank or one
/// of ()[]':;, (a quote doubled inside).
/// @throws InvalidArgument naming "tree" for a malformed tree, "labels" unless there is one per leaf.
std::string toNewick(const Tree& tree, const std::vector<std::string>& labels);

/// Reads a binary Newick tree as toNewick() writes it: every leaf labelled, every non-root branch with a
/// non-negative length, an optional root length (ignored), blanks between tokens, no comments and no
/// internal labels. Leaves are numbered in order of appearance, internal nodes by height; a node's height
/// is the largest of its children's height + branch length (exact for ultrametric trees such as UPGMA's).
/// `labels` (may be null) receives the leaf labels, unquoted.
/// @throws ParseError ("newick", line, field, what) for malformed text.
Tree parseNewick(const std::string& text, std::vector<std::string>* labels);

}  // namespace ppp::generator
