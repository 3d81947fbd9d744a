#include "ppp_generator/newick.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <iterator>
#include <numeric>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp::generator {

namespace {

constexpr const char* kSpecial = "()[]':;,";

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool isSpecial(char c) { return c != '\0' && std::strchr(kSpecial, c) != nullptr; }
/// Control characters (NUL included) have no place in a label, quoted or not.
bool isControl(char c) { return (static_cast<unsigned char>(c) < 0x20 && !isBlank(c)) || c == 0x7f; }

void appendLabel(std::string* out, const std::string& label) {
  const bool quote =
      label.empty() || std::any_of(label.begin(), label.end(), [](char c) { return isBlank(c) || isSpecial(c); });
  if (!quote) {
    *out += label;
    return;
  }
  *out += '\'';
  for (const char c : label) {
    if (c == '\'') *out += '\'';
    *out += c;
  }
  *out += '\'';
}

void appendLength(std::string* out, double length) { *out += ':' + formatGeneral(length, 10); }

/// A node as read, before leaves and merges are renumbered.
struct RawNode {
  int left = -1;
  int right = -1;
  double length = 0;
  bool has_length = false;
  double height = 0;
};

/// Iterative reader (no recursion, so deep trees cannot overflow the stack).
class NewickReader {
 public:
  explicit NewickReader(const std::string& text) : text_(text) {}

  Tree read(std::vector<std::string>* labels) {
    skipBlanks();
    if (pos_ == text_.size()) fail("tree", "empty text, expected a Newick tree ending in ';'");
    std::vector<std::vector<int>> open;  // children read so far of every unclosed '('
    int current = readSubtreeStart(&open);
    while (true) {
      readLength(current);
      skipBlanks();
      if (open.empty()) {
        expectEnd();
        break;
      }
      if (!raw_[static_cast<std::size_t>(current)].has_length) fail("branch length", "missing ':length' after a node");
      std::vector<int>& siblings = open.back();
      siblings.push_back(current);
      const char c = peek();
      if (c == ',') {
        if (siblings.size() == 2) fail("tree", "a third child in one clade; only binary trees (as UPGMA writes)");
        ++pos_;
        current = readSubtreeStart(&open);
      } else if (c == ')') {
        if (siblings.size() == 1) fail("tree", "a clade with one child; only binary trees (as UPGMA writes)");
        ++pos_;
        current = addInternal(siblings[0], siblings[1]);
        open.pop_back();
        skipBlanks();
        if (peek() == '\'' || (pos_ < text_.size() && !isSpecial(peek()))) {
          fail("label", "internal node labels are not supported");
        }
      } else if (c == '\0') {
        fail("tree", "unbalanced parentheses: text ends with " + std::to_string(open.size()) + " '(' unclosed");
      } else if (c == ';') {
        fail("tree", "unbalanced parentheses: ';' with " + std::to_string(open.size()) + " '(' unclosed");
      } else {
        fail("tree", std::string("unexpected '") + c + "', expected ',' or ')'");
      }
    }
    return build(labels);
  }

 private:
  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    const auto at = text_.begin() + static_cast<std::ptrdiff_t>(std::min(pos_, text_.size()));
    const int line = 1 + static_cast<int>(std::count(text_.begin(), at, '\n'));
    const auto line_start = std::find(std::make_reverse_iterator(at), text_.rend(), '\n').base();
    const long column = 1 + (at - line_start);
    throw ParseError("newick", line, field, what + " (column " + std::to_string(column) + ")");
  }

  void skipBlanks() {
    while (pos_ < text_.size() && isBlank(text_[pos_])) ++pos_;
  }

  char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }

  /// Reads '('s up to and including the first leaf; returns the leaf.
  int readSubtreeStart(std::vector<std::vector<int>>* open) {
    while (true) {
      skipBlanks();
      const char c = peek();
      if (c == '(') {
        open->emplace_back();
        ++pos_;
      } else if (c == '\0') {
        fail("tree", "unexpected end of text, expected a label or '('");
      } else if (c == '[') {
        fail("tree", "comments in [] are not supported");
      } else if (c == '\'' || !isSpecial(c)) {
        return addLeaf(readLabel());
      } else {
        fail("label", std::string("unexpected '") + c + "', expected a label or '('");
      }
    }
  }

  [[noreturn]] void failControl(char c) {
    fail("label", "control character (byte " + std::to_string(static_cast<unsigned char>(c)) + ") in a label");
  }

  std::string readLabel() {
    std::string label;
    if (peek() == '\'') {
      ++pos_;
      while (true) {
        if (pos_ >= text_.size()) fail("label", "unterminated quoted label");
        const char c = text_[pos_++];
        if (isControl(c)) failControl(c);
        if (c != '\'') {
          label += c;
        } else if (peek() == '\'') {
          label += '\'';
          ++pos_;
        } else {
          break;
        }
      }
      return label;
    }
    while (pos_ < text_.size() && !isBlank(text_[pos_]) && !isSpecial(text_[pos_])) {
      if (isControl(text_[pos_])) failControl(text_[pos_]);
      label += text_[pos_++];
    }
    return label;
  }

  void readLength(int node) {
    skipBlanks();
    if (peek() != ':') return;
    ++pos_;
    skipBlanks();
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !isBlank(text_[pos_]) && !isSpecial(text_[pos_])) ++pos_;
    const std::string token = text_.substr(start, pos_ - start);
    double value = 0;
    const char* first = token.data();
    const char* last = token.data() + token.size();
    if (!token.empty() && *first == '+') ++first;
    const auto result = std::from_chars(first, last, value);
    if (token.empty() || result.ec != std::errc() || result.ptr != last || !std::isfinite(value)) {
      pos_ = start;
      fail("branch length", "'" + token + "' is not a number");
    }
    if (value < 0) {
      pos_ = start;
      fail("branch length", "'" + token + "' is negative, expected a length >= 0");
    }
    RawNode& raw = raw_[static_cast<std::size_t>(node)];
    raw.length = value;
    raw.has_length = true;
  }

  void expectEnd() {
    if (peek() == ')') fail("tree", "unbalanced parentheses: ')' without a matching '('");
    if (peek() != ';') fail("tree", pos_ == text_.size() ? "missing ';' at the end" : "expected ';' after the tree");
    ++pos_;
    skipBlanks();
    if (pos_ != text_.size()) fail("tree", "trailing characters after ';'");
  }

  int addLeaf(std::string label) {
    raw_.emplace_back();
    leaf_labels_.push_back(std::move(label));
    return static_cast<int>(raw_.size()) - 1;
  }

  int addInternal(int left, int right) {
    RawNode node;
    node.left = left;
    node.right = right;
    const RawNode& l = raw_[static_cast<std::size_t>(left)];
    const RawNode& r = raw_[static_cast<std::size_t>(right)];
    node.height = std::max(l.height + l.length, r.height + r.length);
    raw_.push_back(node);
    return static_cast<int>(raw_.size()) - 1;
  }

  /// Renumbers: leaves in order of appearance, then internal nodes by height (ties keep closing order,
  /// which puts children before parents).
  Tree build(std::vector<std::string>* labels) {
    std::vector<int> leaves, internal;
    for (std::size_t i = 0; i < raw_.size(); ++i) (raw_[i].left < 0 ? leaves : internal).push_back(static_cast<int>(i));
    std::stable_sort(internal.begin(), internal.end(), [this](int a, int b) {
      return raw_[static_cast<std::size_t>(a)].height < raw_[static_cast<std::size_t>(b)].height;
    });
    std::vector<int> index(raw_.size());
    for (std::size_t i = 0; i < leaves.size(); ++i) index[static_cast<std::size_t>(leaves[i])] = static_cast<int>(i);
    for (std::size_t i = 0; i < internal.size(); ++i) {
      index[static_cast<std::size_t>(internal[i])] = static_cast<int>(leaves.size() + i);
    }
    Tree tree;
    tree.nodes.resize(raw_.size());
    for (std::size_t i = 0; i < raw_.size(); ++i) {
      const RawNode& raw = raw_[i];
      TreeNode& node = tree.nodes[static_cast<std::size_t>(index[i])];
      if (raw.left < 0) continue;
      node.left = index[static_cast<std::size_t>(raw.left)];
      node.right = index[static_cast<std::size_t>(raw.right)];
      node.height = raw.height;
    }
    for (TreeNode& node : tree.nodes) {
      if (node.left >= 0) {
        node.size = tree.nodes[static_cast<std::size_t>(node.left)].size +
                    tree.nodes[static_cast<std::size_t>(node.right)].size;
      }
    }
    if (labels != nullptr) *labels = std::move(leaf_labels_);
    return tree;
  }

  const std::string& text_;
  std::size_t pos_ = 0;
  std::vector<RawNode> raw_;
  std::vector<std::string> leaf_labels_;
};

}  // namespace

std::string toNewick(const Tree& tree, const std::vector<std::string>& labels) {
  validateTree(tree);
  if (labels.size() != static_cast<std::size_t>(tree.leafCount())) {
    throw InvalidArgument("labels", std::to_string(labels.size()) + " labels for " +
                                        std::to_string(tree.leafCount()) + " leaves, expected one per leaf");
  }
  std::string out;
  struct Frame {
    int node;
    int state;  // 0: not started, 1: left written, 2: right written
  };
  std::vector<Frame> stack{{tree.root(), 0}};
  const auto appendBranch = [&](int node) {
    const int parent = stack.empty() ? -1 : stack.back().node;
    if (parent >= 0) {
      appendLength(&out, tree.nodes[static_cast<std::size_t>(parent)].height -
                             tree.nodes[static_cast<std::size_t>(node)].height);
    }
  };
  while (!stack.empty()) {
    Frame& frame = stack.back();
    const TreeNode& node = tree.nodes[static_cast<std::size_t>(frame.node)];
    if (node.left < 0) {
      const int leaf = frame.node;
      stack.pop_back();
      appendLabel(&out, labels[static_cast<std::size_t>(leaf)]);
      appendBranch(leaf);
    } else if (frame.state == 0) {
      out += '(';
      frame.state = 1;
      stack.push_back({node.left, 0});
    } else if (frame.state == 1) {
      out += ',';
      frame.state = 2;
      stack.push_back({node.right, 0});
    } else {
      const int done = frame.node;
      stack.pop_back();
      out += ')';
      appendBranch(done);
    }
  }
  out += ';';
  return out;
}

Tree parseNewick(const std::string& text, std::vector<std::string>* labels) {
  return NewickReader(text).read(labels);
}

}  // namespace ppp::generator
