#pragma once

#include <string>
#include <vector>

#include "ppp_core/grid.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_generator/taxonomy.hpp"

namespace ppp::generator {

/// Standard base64 (RFC 4648 section 4, with '=' padding) of raw bytes, for data URIs.
std::string base64Encode(const std::string& bytes);

/// A small PNG of a PPP (no grid lines, the optional route drawn), its longer side at most
/// `max_side_pixels` unless the grid has more cells than that (then one pixel per cell).
/// @throws InvalidArgument naming "max_side_pixels" when it is below 1, or as ppp::renderProblemRgb().
std::string thumbnailPng(const ppp::Problem& problem, const std::vector<ppp::Cell>& path = {},
                         int max_side_pixels = 80);

/// A self-contained HTML page (no scripts, fonts or links to fetch) drawing the tree as an inline SVG
/// dendrogram: leaves in a column on the left, each with its label and its thumbnail embedded as a
/// data:image/png URI, merge height on the horizontal axis with a scale. `thumbnail_pngs` holds raw PNG
/// bytes per leaf (an empty entry draws none) or is empty. Labels and title are HTML-escaped.
/// @throws InvalidArgument naming "tree" for a malformed tree, "labels" unless there is one per leaf,
/// "thumbnails" unless there is one per leaf or none.
std::string treeHtml(const Tree& tree, const std::vector<std::string>& labels,
                     const std::vector<std::string>& thumbnail_pngs, const std::string& title);

}  // namespace ppp::generator
