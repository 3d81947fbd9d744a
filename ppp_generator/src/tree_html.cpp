#include "ppp_generator/tree_html.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/picture.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp::generator {

namespace {

// Layout, in SVG pixels.
constexpr double kThumbSide = 44;
constexpr double kRowWithThumbs = 52;
constexpr double kRowWithoutThumbs = 22;
constexpr double kMargin = 12;
constexpr double kLabelCharWidth = 7.8;  // 13px monospace
constexpr double kTreeWidth = 640;
constexpr double kAxisHeight = 56;

/// A coordinate with one decimal.
std::string px(double value) { return formatFixed(value, 1); }

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:16px;color:#222;background:#fff}"
    "h1{font-size:20px;margin:0 0 4px}p{margin:0 0 12px;color:#555;font-size:13px}"
    "svg text{font-size:13px}.label{font-family:monospace}"
    ".branch{fill:none;stroke:#1d3f72;stroke-width:1.5}.leader{stroke:#bbb;stroke-dasharray:2 3}"
    ".grid{stroke:#eee}.axis{stroke:#444}.node{fill:#1d3f72}.tick{fill:#444;font-size:11px}"
    ".thumb{image-rendering:pixelated}.frame{fill:none;stroke:#999}";

}  // namespace

std::string base64Encode(const std::string& bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= bytes.size(); i += 3) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 | static_cast<unsigned char>(bytes[i + 1]) << 8 |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[v >> 18 & 63];
    out += kAlphabet[v >> 12 & 63];
    out += kAlphabet[v >> 6 & 63];
    out += kAlphabet[v & 63];
  }
  const std::size_t rest = bytes.size() - i;
  if (rest > 0) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (rest == 2) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += kAlphabet[v >> 18 & 63];
    out += kAlphabet[v >> 12 & 63];
    out += rest == 2 ? kAlphabet[v >> 6 & 63] : '=';
    out += '=';
  }
  return out;
}

std::string thumbnailPng(const ppp::Problem& problem, const std::vector<ppp::Cell>& path, int max_side_pixels) {
  if (max_side_pixels < 1) {
    throw InvalidArgument("max_side_pixels", "expected at least 1, got " + std::to_string(max_side_pixels));
  }
  ppp::PictureOptions options;
  options.grid_lines = false;
  options.cell_pixels = std::clamp(max_side_pixels / std::max({problem.width, problem.height, 1}), 1, 256);
  const std::vector<std::uint8_t> rgb = ppp::renderProblemRgb(problem, path, options);
  return ppp::encodePng(rgb, ppp::pictureWidth(problem.width, options), ppp::pictureHeight(problem.height, options));
}

std::string treeHtml(const Tree& tree, const std::vector<std::string>& labels,
                     const std::vector<std::string>& thumbnail_pngs, const std::string& title) {
  const std::vector<int> order = leafOrder(tree);  // validates the tree
  const std::size_t n = order.size();
  if (labels.size() != n) {
    throw InvalidArgument("labels", std::to_string(labels.size()) + " labels for " + std::to_string(n) +
                                        " leaves, expected one per leaf");
  }
  if (!thumbnail_pngs.empty() && thumbnail_pngs.size() != n) {
    throw InvalidArgument("thumbnails", std::to_string(thumbnail_pngs.size()) + " thumbnails for " +
                                            std::to_string(n) + " leaves, expected one per leaf or none");
  }
  const bool thumbs = std::any_of(thumbnail_pngs.begin(), thumbnail_pngs.end(),
                                  [](const std::string& png) { return !png.empty(); });

  std::size_t longest = 1;
  for (const std::string& label : labels) longest = std::max(longest, displayLength(label));
  const double row = thumbs ? kRowWithThumbs : kRowWithoutThumbs;
  const double thumb_x = kMargin;
  const double label_x = thumbs ? thumb_x + kThumbSide + 10 : kMargin;
  const double tree_x = label_x + static_cast<double>(longest) * kLabelCharWidth + 16;
  const double axis_y = kMargin + static_cast<double>(n) * row + 8;
  const double svg_width = tree_x + kTreeWidth + 48;
  const double svg_height = axis_y + kAxisHeight;
  const double root_height = tree.nodes.back().height;
  const double top = root_height > 0 ? root_height : 1;
  const auto xOf = [&](double height) { return tree_x + height / top * kTreeWidth; };

  std::vector<double> y(tree.nodes.size());
  for (std::size_t r = 0; r < n; ++r) y[static_cast<std::size_t>(order[r])] = kMargin + (static_cast<double>(r) + 0.5) * row;
  for (std::size_t i = n; i < tree.nodes.size(); ++i) {
    y[i] = 0.5 * (y[static_cast<std::size_t>(tree.nodes[i].left)] + y[static_cast<std::size_t>(tree.nodes[i].right)]);
  }

  std::string svg;
  svg += "<svg width=\"" + px(svg_width) + "\" height=\"" + px(svg_height) + "\" viewBox=\"0 0 " + px(svg_width) +
         " " + px(svg_height) + "\" role=\"img\" aria-label=\"dendrogram of " + std::to_string(n) + " PPPs\">\n";

  const double step = tickStep(top);
  std::string ticks;
  for (int t = 0; t * step <= top * (1 + 1e-9); ++t) {
    const double x = xOf(t * step);
    svg += "<line class=\"grid\" x1=\"" + px(x) + "\" y1=\"" + px(kMargin) + "\" x2=\"" + px(x) + "\" y2=\"" +
           px(axis_y) + "\"/>\n";
    ticks += "<line class=\"axis\" x1=\"" + px(x) + "\" y1=\"" + px(axis_y) + "\" x2=\"" + px(x) + "\" y2=\"" +
             px(axis_y + 5) + "\"/><text class=\"tick\" x=\"" + px(x) + "\" y=\"" + px(axis_y + 18) +
             "\" text-anchor=\"middle\">" + formatGeneral(t * step, 6) + "</text>\n";
  }

  std::string branches;
  std::string nodes;
  for (std::size_t i = n; i < tree.nodes.size(); ++i) {
    const TreeNode& node = tree.nodes[i];
    const double x = xOf(node.height);
    for (const int child : {node.left, node.right}) {
      const std::size_t c = static_cast<std::size_t>(child);
      branches += "M" + px(xOf(tree.nodes[c].height)) + " " + px(y[c]) + "H" + px(x);
    }
    branches += "M" + px(x) + " " + px(y[static_cast<std::size_t>(node.left)]) + "V" +
                px(y[static_cast<std::size_t>(node.right)]);
    nodes += "<circle class=\"node\" cx=\"" + px(x) + "\" cy=\"" + px(y[i]) + "\" r=\"2.5\"><title>height " +
             formatGeneral(node.height, 6) + ", " + std::to_string(node.size) + " PPPs</title></circle>\n";
  }
  if (!branches.empty()) svg += "<path class=\"branch\" d=\"" + branches + "\"/>\n";
  svg += nodes;

  for (std::size_t r = 0; r < n; ++r) {
    const std::size_t leaf = static_cast<std::size_t>(order[r]);
    const std::string label = escapeMarkup(labels[leaf]);
    const double label_end = label_x + static_cast<double>(displayLength(labels[leaf])) * kLabelCharWidth + 4;
    svg += "<g><title>" + label + " (PPP " + std::to_string(leaf) + ")</title>";
    if (!thumbnail_pngs.empty() && !thumbnail_pngs[leaf].empty()) {
      svg += "<image class=\"thumb\" x=\"" + px(thumb_x) + "\" y=\"" + px(y[leaf] - kThumbSide / 2) + "\" width=\"" +
             px(kThumbSide) + "\" height=\"" + px(kThumbSide) +
             "\" preserveAspectRatio=\"xMidYMid meet\" href=\"data:image/png;base64," +
             base64Encode(thumbnail_pngs[leaf]) + "\"/><rect class=\"frame\" x=\"" + px(thumb_x) + "\" y=\"" +
             px(y[leaf] - kThumbSide / 2) + "\" width=\"" + px(kThumbSide) + "\" height=\"" + px(kThumbSide) + "\"/>";
    }
    svg += "<text class=\"label\" x=\"" + px(label_x) + "\" y=\"" + px(y[leaf]) + "\" dy=\"0.35em\">" + label +
           "</text>";
    if (label_end < tree_x) {
      svg += "<line class=\"leader\" x1=\"" + px(label_end) + "\" y1=\"" + px(y[leaf]) + "\" x2=\"" + px(tree_x) +
             "\" y2=\"" + px(y[leaf]) + "\"/>";
    }
    svg += "</g>\n";
  }

  svg += "<line class=\"axis\" x1=\"" + px(tree_x) + "\" y1=\"" + px(axis_y) + "\" x2=\"" + px(xOf(top)) +
         "\" y2=\"" + px(axis_y) + "\"/>\n" + ticks;
  svg += "<text x=\"" + px(tree_x + kTreeWidth / 2) + "\" y=\"" + px(axis_y + 40) +
         "\" text-anchor=\"middle\">merge height (half the average distance between the merged groups)</text>\n";
  svg += "</svg>\n";

  const std::string escaped_title = escapeMarkup(title);
  std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
                     escaped_title + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<h1>" +
                     escaped_title + "</h1>\n<p>" + std::to_string(n) +
                     " PPPs; root height " + formatGeneral(root_height, 6) +
                     ". Hover over a node for its height and size, over a PPP for its index.</p>\n";
  html += svg;
  html += "</body>\n</html>\n";
  return html;
}

}  // namespace ppp::generator
