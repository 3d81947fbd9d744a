#include "ppp_generator/newick.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/rng.hpp"
#include "hand_tree.hpp"

namespace ppp::generator {
namespace {

using test::handTree;

const std::vector<std::string> kHandLabels{"a", "b", "c", "d", "e"};

/// Every clade as its sorted leaf labels, mapped to its height: equal maps mean the same tree.
std::map<std::vector<std::string>, double> clades(const Tree& tree, const std::vector<std::string>& labels) {
  std::vector<std::vector<std::string>> below(tree.nodes.size());
  std::map<std::vector<std::string>, double> out;
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
    const TreeNode& node = tree.nodes[i];
    if (node.left < 0) {
      below[i] = {labels[i]};
    } else {
      below[i] = below[static_cast<std::size_t>(node.left)];
      const auto& right = below[static_cast<std::size_t>(node.right)];
      below[i].insert(below[i].end(), right.begin(), right.end());
      std::sort(below[i].begin(), below[i].end());
    }
    out[below[i]] = node.height;
  }
  return out;
}

Tree randomTree(Rng& rng, int n) {
  Eigen::MatrixXd points(n, 14);
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < 14; ++c) points(r, c) = rng.uniform01();
  }
  return upgma(euclideanDistances(points));
}

TEST(NewickTest, HandTreeExactly) {
  EXPECT_EQ(toNewick(handTree(), kHandLabels), "(((a:8.5,b:8.5):2.5,e:11):5.5,(c:14,d:14):2.5);");
}

TEST(NewickTest, SmallestTrees) {
  Tree one;
  one.nodes.resize(1);
  EXPECT_EQ(toNewick(one, {"only"}), "only;");
  Eigen::MatrixXd d(3, 3);
  d << 0, 1, 3.5,  //
      1, 0, 3.5,   //
      3.5, 3.5, 0;
  EXPECT_EQ(toNewick(upgma(d), {"a", "b", "c"}), "((a:0.5,b:0.5):1.25,c:1.75);");
}

TEST(NewickTest, SpecialLabelsAreQuoted) {
  Eigen::MatrixXd d(3, 3);
  d << 0, 2, 4,  //
      2, 0, 4,   //
      4, 4, 0;
  const std::vector<std::string> labels{"PPP 1", "it's", "x:(y),z;[w]"};
  const std::string text = toNewick(upgma(d), labels);
  EXPECT_EQ(text, "(('PPP 1':1,'it''s':1):1,'x:(y),z;[w]':2);");
  std::vector<std::string> back;
  parseNewick(text, &back);
  EXPECT_EQ(back, labels);
}

TEST(NewickTest, ParsesHandTree) {
  std::vector<std::string> labels;
  const Tree tree = parseNewick(" (((a:8.5, b:8.5):2.5,e:11):5.5,\n(c:14,d:14):2.5):0;\n", &labels);
  EXPECT_EQ(labels, (std::vector<std::string>{"a", "b", "e", "c", "d"}));
  ASSERT_NO_THROW(validateTree(tree));
  EXPECT_EQ(clades(tree, labels), clades(handTree(), kHandLabels));
  // Internal nodes come in order of height, like UPGMA's merge order.
  EXPECT_DOUBLE_EQ(tree.nodes[5].height, 8.5);
  EXPECT_DOUBLE_EQ(tree.nodes[6].height, 11);
  EXPECT_DOUBLE_EQ(tree.nodes[7].height, 14);
  EXPECT_DOUBLE_EQ(tree.nodes[8].height, 16.5);
  EXPECT_EQ(tree.nodes[8].size, 5);
  EXPECT_EQ(parseNewick("x;", nullptr).leafCount(), 1);
}

TEST(NewickTest, OutputParsesBackToTheSameTopology) {
  Rng rng(2024);
  for (int n = 2; n <= 60; ++n) {
    SCOPED_TRACE("n = " + std::to_string(n));
    const Tree tree = randomTree(rng, n);
    std::vector<std::string> labels;
    for (int i = 0; i < n; ++i) labels.push_back("p" + std::to_string(i));
    std::vector<std::string> parsed_labels;
    const Tree parsed = parseNewick(toNewick(tree, labels), &parsed_labels);
    ASSERT_NO_THROW(validateTree(parsed));
    ASSERT_EQ(parsed.leafCount(), n);
    const auto expected = clades(tree, labels);
    const auto actual = clades(parsed, parsed_labels);
    ASSERT_EQ(actual.size(), expected.size());
    for (const auto& [clade, height] : expected) {
      const auto found = actual.find(clade);
      ASSERT_NE(found, actual.end()) << "a clade of " << clade.size() << " leaves is missing";
      EXPECT_NEAR(found->second, height, 1e-6);
    }
  }
}

TEST(NewickTest, MalformedTextThrowsParseError) {
  const std::vector<std::string> bad{
      "",                        // empty
      "   \t ",                  // blank
      "((a:1,b:1):1,c:2;",       // unbalanced: '(' unclosed
      "(a:1,b:1)):1;",           // unbalanced: extra ')'
      "(a:1,b:1)",               // missing ';'
      "(a:1,b:x);",              // non-numeric length
      "(a:1,b:1e);",             // malformed number
      "(a:1,b:-1);",             // negative length
      "(a:1,b:nan);",            // not finite
      "(a:1,b:1); extra",        // trailing garbage
      "(a:1,b:1);;",             // trailing garbage
      "(a:1,b);",                // missing length
      "(a:1,b:1,c:1);",          // not binary
      "(a:1);",                  // one child
      "(:1,b:1);",               // missing label
      "(a:1,b:1)root;",          // internal label
      "(a:1,b:1)'root';",        // quoted internal label
      "('a:1,b:1);",             // unterminated quote
      "(a[comment]:1,b:1);",     // comments
      "a b;",                    // two labels
      ";",                       // no tree
      // Found by newick_fuzz: a NUL inside a quoted label was read, then toNewick's output was refused.
      std::string("((a:0.5,b:0.5):1.24,'\0\0d':1.75);", 32),
      std::string("(a\0b:1,c:1);", 12),  // NUL in an unquoted label
      "(a\x01:1,b:1);",          // other control characters
      "('a\x7f':1,b:1);",
  };
  for (const std::string& text : bad) {
    try {
      parseNewick(text, nullptr);
      ADD_FAILURE() << "accepted '" << text << "'";
    } catch (const ParseError& e) {
      EXPECT_EQ(e.file(), "newick") << e.what();
      EXPECT_EQ(e.line(), 1) << e.what();
    }
  }
}

TEST(NewickTest, ControlCharactersInALabelAreNamed) {
  try {
    parseNewick(std::string("((a:0.5,b:0.5):1.24,'\0d':1.75);", 31), nullptr);
    ADD_FAILURE() << "accepted a NUL in a label";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("label: control character (byte 0) in a label"), std::string::npos) << e.what();
  }
}

TEST(NewickTest, ErrorsNameTheLine) {
  try {
    parseNewick("((a:1,\nb:1):1,\nc:oops);", nullptr);
    FAIL() << "accepted";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.field(), "branch length");
    EXPECT_EQ(std::string(e.what()), "newick:3: branch length: 'oops' is not a number (column 3)");
  }
}

TEST(NewickTest, RejectsBadArguments) {
  EXPECT_THROW(toNewick(handTree(), {"a", "b"}), InvalidArgument);
  EXPECT_THROW(toNewick(Tree{}, {}), InvalidArgument);
}

}  // namespace
}  // namespace ppp::generator
