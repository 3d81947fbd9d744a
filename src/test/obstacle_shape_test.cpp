// obstacleShape: equal keys exactly for maps whose obstacles are one another's moved, mirrored or rotated.
#include "ppp_core/obstacle_shape.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

#include "grid_picture.hpp"

namespace ppp {
namespace {

using test::picture;

TEST(ObstacleShapeTest, CropsToTheObstaclesAndReadsTheSmallestOfTheEightSymmetries) {
  EXPECT_EQ(obstacleShape(picture({"....", "....", "...."}).grid), "0x0:");
  EXPECT_EQ(obstacleShape(picture({"....", "..#.", "...."}).grid), "1x1:#");
  // An L of three cells: its 8 readings are the 2x2 squares with one free corner; '#' < '.' in ASCII, so the
  // smallest has the free corner last.
  EXPECT_EQ(obstacleShape(picture({".....", ".#...", ".##..", "....."}).grid), "2x2:##/#.");
  // A bar of three reads as 1x3 or 3x1: "1x3:#/#/#" is the smaller.
  EXPECT_EQ(obstacleShape(picture({"#..", "#..", "#.."}).grid), "1x3:#/#/#");
  EXPECT_EQ(obstacleShape(picture({"...", "###", "..."}).grid), "1x3:#/#/#");
  // Two cells touching at a corner, either diagonal.
  EXPECT_EQ(obstacleShape(picture({"#.", ".#"}).grid), obstacleShape(picture({"...", ".#.", "#.."}).grid));
  EXPECT_NE(obstacleShape(picture({"#.", ".#"}).grid), obstacleShape(picture({"##", ".."}).grid));
}

/// The cells of a pattern, moved so that its smallest x and y are 0 (an independent normal form).
std::set<std::pair<int, int>> normalised(std::vector<std::pair<int, int>> cells) {
  int x0 = 1 << 20, y0 = 1 << 20;
  for (const auto& [x, y] : cells) x0 = std::min(x0, x), y0 = std::min(y0, y);
  std::set<std::pair<int, int>> out;
  for (const auto& [x, y] : cells) out.insert({x - x0, y - y0});
  return out;
}

/// Whether one set of cells is the other's moved, mirrored or rotated, by trying the 8 maps (x, y) -> (±x, ±y)
/// and (±y, ±x) on coordinates.
bool sameUpToSymmetry(const std::vector<std::pair<int, int>>& a, const std::vector<std::pair<int, int>>& b) {
  const std::set<std::pair<int, int>> target = normalised(b);
  for (int map = 0; map < 8; ++map) {
    std::vector<std::pair<int, int>> moved;
    for (auto [x, y] : a) {
      if (map & 4) std::swap(x, y);
      moved.push_back({map & 1 ? -x : x, map & 2 ? -y : y});
    }
    if (normalised(moved) == target) return true;
  }
  return false;
}

// Every non-empty pattern of a 3x3 window, placed at two different offsets of a 6x6 map: obstacleShape's keys are
// equal exactly when the coordinate maps say the two are the same shape (511 x 511 pairs).
TEST(ObstacleShapeTest, AgreesWithAllCoordinateSymmetriesOnEveryThreeByThreePattern) {
  std::vector<std::vector<std::pair<int, int>>> patterns;
  std::vector<std::string> keys;
  for (int bits = 1; bits < 512; ++bits) {
    std::vector<std::pair<int, int>> cells;
    Grid grid(6, 6);
    const int dx = bits % 4, dy = (bits / 4) % 4;  // each pattern somewhere else on the map
    for (int i = 0; i < 9; ++i) {
      if (!(bits >> i & 1)) continue;
      cells.push_back({i % 3, i / 3});
      grid.setObstacle(Cell{i % 3 + dx, i / 3 + dy}, true);
    }
    patterns.push_back(cells);
    keys.push_back(obstacleShape(grid));
  }
  int shapes = 0;
  for (std::size_t a = 0; a < patterns.size(); ++a) {
    bool first = true;
    for (std::size_t b = 0; b < patterns.size(); ++b) {
      const bool same = sameUpToSymmetry(patterns[a], patterns[b]);
      ASSERT_EQ(keys[a] == keys[b], same) << keys[a] << " against " << keys[b];
      if (same && b < a) first = false;
    }
    shapes += first ? 1 : 0;
  }
  EXPECT_EQ(std::set<std::string>(keys.begin(), keys.end()).size(), static_cast<std::size_t>(shapes));
}

}  // namespace
}  // namespace ppp
