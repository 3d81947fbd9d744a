#include "ppp_core/random_problem.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace ppp {
namespace {

TEST(RandomProblemTest, TheDefaultMixIsTheFiveShapesInTheirOrder) {
  const RandomObstacleOptions defaults;
  EXPECT_EQ(defaults.shapes, std::vector<Shape>(std::begin(kAllShapes), std::end(kAllShapes)));
  EXPECT_EQ(shapeListText(defaults.shapes), "hbar,vbar,diag_down,diag_up,block");
}

TEST(RandomProblemTest, DrawsOnlyTheListedShapesEachEntryEquallyLikely) {
  RandomObstacleOptions options;
  options.shapes = {Shape::HorizontalBar, Shape::HorizontalBar, Shape::Block};
  Rng rng(12);
  std::map<Shape, int> drawn;
  const int draws = 6000;
  for (int i = 0; i < draws; ++i) ++drawn[randomObstacle(rng, 20, 20, options).shape];
  EXPECT_EQ(drawn.size(), 2u);
  // hbar listed twice of three: binomial(6000, 2/3), standard deviation sqrt(6000 * 2/9) = 36.5.
  EXPECT_NEAR(drawn[Shape::HorizontalBar], 4000, 4 * 36.5);
  EXPECT_EQ(drawn[Shape::HorizontalBar] + drawn[Shape::Block], draws);
}

TEST(RandomProblemTest, BarsTakeEveryLengthBetweenTheShortestAndTheLongest) {
  RandomObstacleOptions options;
  options.shapes = {Shape::DiagonalDown, Shape::VerticalBar};
  options.min_bar_length = 4;
  options.max_bar_length = 7;
  Rng rng(3);
  std::map<int, int> lengths;
  for (int i = 0; i < 2000; ++i) ++lengths[randomObstacle(rng, 20, 20, options).length];
  EXPECT_EQ(lengths.size(), 4u);
  EXPECT_EQ(lengths.begin()->first, 4);
  EXPECT_EQ(lengths.rbegin()->first, 7);
  // A shortest bar longer than the longest is capped: every bar is the longest (half of 20 by default).
  options.min_bar_length = 30;
  options.max_bar_length = 0;
  for (int i = 0; i < 200; ++i) EXPECT_EQ(randomObstacle(rng, 20, 20, options).length, 10);
}

TEST(RandomProblemTest, ShapeListsParseAndBadOnesAreRefusedSayingWhy) {
  std::vector<Shape> shapes;
  EXPECT_EQ(shapeListProblem("hbar, vbar,block", &shapes), "");
  EXPECT_EQ(shapes, (std::vector<Shape>{Shape::HorizontalBar, Shape::VerticalBar, Shape::Block}));
  EXPECT_EQ(shapeListProblem(shapeListText(shapes), &shapes), "");
  EXPECT_EQ(shapeListText(shapes), "hbar,vbar,block");
  const std::string expected = "; expected keywords among hbar, vbar, diag_down, diag_up, block separated by commas";
  EXPECT_EQ(shapeListProblem("circle", &shapes), "unknown shape 'circle' in 'circle'" + expected);
  EXPECT_EQ(shapeListProblem("", &shapes), "unknown shape '' in ''" + expected);
  EXPECT_EQ(shapeListProblem("hbar,,vbar", &shapes), "unknown shape '' in 'hbar,,vbar'" + expected);
}

}  // namespace
}  // namespace ppp
