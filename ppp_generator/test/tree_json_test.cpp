#include "ppp_generator/tree_json.hpp"

#include <gtest/gtest.h>

#include "ppp_core/error.hpp"

namespace ppp::generator {
namespace {

TEST(TreeJsonTest, NestedObjectsWithNamesIndicesAndHeights) {
  // (a,b) merge at distance 1 (height 0.5); c joins at distance 3.5 (height 1.75).
  Eigen::MatrixXd d(3, 3);
  d << 0, 1, 3.5,  //
      1, 0, 3.5,   //
      3.5, 3.5, 0;
  const nlohmann::json expected = nlohmann::json::parse(R"({
    "height": 1.75, "size": 3, "children": [
      {"height": 0.5, "size": 2, "children": [
        {"name": "a", "index": 0, "height": 0.0},
        {"name": "b", "index": 1, "height": 0.0}]},
      {"name": "c", "index": 2, "height": 0.0}]})");
  EXPECT_EQ(treeToJson(upgma(d), {"a", "b", "c"}), expected);
}

TEST(TreeJsonTest, SingleLeafAndBadLabels) {
  const Tree one = upgma(Eigen::MatrixXd::Zero(1, 1));
  EXPECT_EQ(treeToJson(one, {"x"}), nlohmann::json::parse(R"({"name": "x", "index": 0, "height": 0.0})"));
  try {
    treeToJson(one, {});
    FAIL() << "accepted missing labels";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "labels");
  }
}

}  // namespace
}  // namespace ppp::generator
