#include "ppp_generator/tree_html.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/picture.hpp"
#include "hand_tree.hpp"

namespace ppp::generator {
namespace {

using test::handTree;

std::size_t countOf(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

TEST(TreeHtmlTest, Base64Rfc4648Vectors) {
  EXPECT_EQ(base64Encode(""), "");
  EXPECT_EQ(base64Encode("f"), "Zg==");
  EXPECT_EQ(base64Encode("fo"), "Zm8=");
  EXPECT_EQ(base64Encode("foo"), "Zm9v");
  EXPECT_EQ(base64Encode("foob"), "Zm9vYg==");
  EXPECT_EQ(base64Encode("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64Encode("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64Encode(std::string("\xff\xfe\x00\x80", 4)), "//4AgA==");
}

TEST(TreeHtmlTest, SelfContainedPageWithOneThumbnailPerLeaf) {
  const std::vector<std::string> labels{"a", "<b>&co", "c", "d \"quoted\"", "e"};
  std::vector<std::string> thumbnails;
  for (int i = 0; i < 5; ++i) {
    Problem p = Problem::empty(6, 6, 3);
    p.obstacles.push_back(Obstacle{Shape::HorizontalBar, 1, i + 1 < 6 ? i + 1 : 1, 3, 1});
    thumbnails.push_back(thumbnailPng(p));
  }
  const std::string html = treeHtml(handTree(), labels, thumbnails, "Taxonomy <test>");

  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_EQ(countOf(html, "<svg"), 1u);
  EXPECT_EQ(countOf(html, "<image "), 5u);
  EXPECT_EQ(countOf(html, "href=\"data:image/png;base64,iVBORw0KGgo"), 5u);  // the PNG signature, encoded
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_NE(html.find("&lt;b&gt;&amp;co"), std::string::npos);
  EXPECT_NE(html.find("d &quot;quoted&quot;"), std::string::npos);
  EXPECT_EQ(html.find("<b>&co"), std::string::npos);
  EXPECT_NE(html.find("<title>Taxonomy &lt;test&gt;</title>"), std::string::npos);
  EXPECT_NE(html.find(base64Encode(thumbnails[3])), std::string::npos);
  EXPECT_EQ(countOf(html, "<circle"), 4u);  // one per merge
}

TEST(TreeHtmlTest, WithoutThumbnailsAndSingleLeaf) {
  const std::string html = treeHtml(handTree(), {"a", "b", "c", "d", "e"}, {}, "no pictures");
  EXPECT_EQ(countOf(html, "<image"), 0u);
  EXPECT_EQ(countOf(html, "class=\"label\""), 5u);

  Tree one;
  one.nodes.resize(1);
  const std::string single = treeHtml(one, {"alone"}, {}, "one");
  EXPECT_NE(single.find(">alone</text>"), std::string::npos);
}

TEST(TreeHtmlTest, PageGrowsWithTheLeaves) {
  Eigen::MatrixXd d(120, 120);
  for (int i = 0; i < 120; ++i) {
    for (int j = 0; j < 120; ++j) d(i, j) = std::abs(i - j);
  }
  std::vector<std::string> labels;
  for (int i = 0; i < 120; ++i) labels.push_back("ppp-" + std::to_string(i));
  const std::string small = treeHtml(handTree(), {"a", "b", "c", "d", "e"}, {}, "5");
  const std::string large = treeHtml(upgma(d), labels, {}, "120");
  const auto heightOf = [](const std::string& html) {
    const std::size_t at = html.find("height=\"", html.find("<svg")) + 8;
    return std::stod(html.substr(at, html.find('"', at) - at));
  };
  EXPECT_GT(heightOf(large), 10 * heightOf(small));  // 5 -> 120 rows, plus fixed margins and axis
}

TEST(TreeHtmlTest, RejectsMismatchedInputs) {
  try {
    treeHtml(handTree(), {"a"}, {}, "t");
    FAIL() << "accepted one label for five leaves";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "labels");
  }
  try {
    treeHtml(handTree(), {"a", "b", "c", "d", "e"}, {"x", "y"}, "t");
    FAIL() << "accepted two thumbnails for five leaves";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "thumbnails");
  }
  EXPECT_THROW(thumbnailPng(Problem::empty(4, 4, 1), {}, 0), InvalidArgument);
}

}  // namespace
}  // namespace ppp::generator
