// Diversity figures on hand-made sets whose values are worked out in the comments.

#include "ppp_generator/diversity.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ppp_core/error.hpp"

namespace ppp {
namespace generator {
namespace {

/// A 2x2 grid from four characters, row-major: '1' obstacle, '0' free.
Grid row(const std::string& cells) {
  Grid g(2, 2);
  for (int i = 0; i < 4; ++i) g.setObstacle(Cell{i % 2, i / 2}, cells.at(static_cast<std::size_t>(i)) == '1');
  return g;
}

TEST(DiversityTest, CellDifferenceIsTheShareOfDifferingCells) {
  EXPECT_DOUBLE_EQ(cellDifference(row("1000"), row("0100")), 0.5);
  EXPECT_DOUBLE_EQ(cellDifference(row("1100"), row("1100")), 0.0);
  EXPECT_DOUBLE_EQ(cellDifference(row("1100"), row("0011")), 1.0);
}

TEST(DiversityTest, ThreeHandWorkedGrids) {
  // A = 1000, B = 1100, C = 0011: differences AB 1/4, AC 3/4, BC 4/4, mean 2/3. Obstacle density
  // d = (1 + 2 + 2) / 12 = 5/12, 2d(1-d) = 70/144, so diversity = (2/3) / (70/144) = 96/70.
  const std::vector<Grid> set{row("1000"), row("1100"), row("0011")};
  EXPECT_NEAR(setDiversity(set), 96.0 / 70.0, 1e-12);
  // Nearest other: A -> B (1/4), B -> A (1/4), C -> A (3/4).
  EXPECT_EQ(nearestDifferences(set), (std::vector<double>{0.25, 0.25, 0.75}));
}

TEST(DiversityTest, CopiesHaveNoDiversity) {
  EXPECT_DOUBLE_EQ(setDiversity({row("1010"), row("1010"), row("1010")}), 0.0);
  EXPECT_EQ(nearestDifferences({row("1010"), row("1010")}), (std::vector<double>{0.0, 0.0}));
}

TEST(DiversityTest, TwoOppositeHalfFullMapsAreTwiceAsDifferentAsIndependentOnes) {
  // d = 1/2, 2d(1-d) = 1/2; the two maps differ everywhere: 1 / (1/2) = 2.
  EXPECT_DOUBLE_EQ(setDiversity({row("1100"), row("0011")}), 2.0);
}

TEST(DiversityTest, DegenerateSets) {
  EXPECT_DOUBLE_EQ(setDiversity({}), 0.0);
  EXPECT_DOUBLE_EQ(setDiversity({row("1010")}), 0.0);
  EXPECT_EQ(nearestDifferences({row("1010")}), (std::vector<double>{0.0}));
  EXPECT_DOUBLE_EQ(setDiversity({row("0000"), row("0000")}), 0.0);  // d = 0: every map is the same
  EXPECT_DOUBLE_EQ(setDiversity({row("1111"), row("1111")}), 0.0);  // d = 1
}

TEST(DiversityTest, GridsOfDifferentSizesAreRefused) {
  EXPECT_THROW(setDiversity({row("1000"), Grid(3, 2)}), InvalidArgument);
  EXPECT_THROW(cellDifference(Grid(2, 3), row("1000")), InvalidArgument);
}

}  // namespace
}  // namespace generator
}  // namespace ppp
