#include "ppp_core/grid.hpp"

#include <gtest/gtest.h>

#include "ppp_core/error.hpp"

namespace ppp {
namespace {

TEST(GridTest, StartsFreeAndCountsObstacles) {
  Grid grid(3, 2);
  EXPECT_EQ(grid.size(), 6);
  EXPECT_EQ(grid.obstacleCount(), 0);
  grid.setObstacle(Cell{2, 1}, true);
  EXPECT_TRUE(grid.isObstacle(Cell{2, 1}));
  EXPECT_FALSE(grid.isFree(Cell{2, 1}));
  EXPECT_FALSE(grid.isFree(Cell{3, 0}));
  EXPECT_EQ(grid.index(Cell{2, 1}), 5);
  EXPECT_EQ(grid.cellAt(5), (Cell{2, 1}));
  EXPECT_EQ(grid.obstacleCount(), 1);
}

TEST(GridTest, RefusesAbsurdSizesBeforeAllocating) {
  EXPECT_THROW(Grid(1, 5), InvalidArgument);
  EXPECT_THROW(Grid(5, -3), InvalidArgument);
  EXPECT_THROW(Grid(kMaxGridSide + 1, 2), InvalidArgument);
  try {
    Grid(100000, 100000);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("100000x100000"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ppp
