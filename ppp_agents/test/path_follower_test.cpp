// PathFollower: planner paths (map-frame waypoints) checked against the known map and turned into moves.
// Maps are drawn in grid orientation (row 0 at the top); the map frame puts row 0 at the bottom, so a
// waypoint at a cell's centre is (x + 0.5, height - 1 - y + 0.5) at 1 m per cell.
#include "ppp_agents/path_follower.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ppp_core/sensor.hpp"

namespace ppp {
namespace agents {
namespace {

/// A known map drawn as rows of '.' (free), '#' (obstacle) and '?' (unknown).
KnownMap known(const std::vector<std::string>& rows) {
  KnownMap map;
  map.width = static_cast<int>(rows[0].size());
  map.height = static_cast<int>(rows.size());
  for (const std::string& row : rows) {
    for (char c : row) map.cells.push_back(c == '#' ? kScanObstacle : c == '?' ? kScanUnknown : kScanFree);
  }
  return map;
}

/// The map-frame centre of grid cell (x, y) on a map `height` rows tall.
MapPoint centre(int x, int y, int height) { return MapPoint{x + 0.5, height - 1 - y + 0.5}; }

/// Moves the robot along the path until the follower asks for a re-plan; returns the cells visited.
std::vector<Cell> drive(PathFollower& follower, Cell robot, const KnownMap& map) {
  std::vector<Cell> visited{robot};
  while (auto action = follower.next(robot, map)) {
    robot = target(robot, *action);
    visited.push_back(robot);
  }
  return visited;
}

const MapFrame kFrame{4, 3, 1.0};

TEST(PathFollowerTest, SparseWaypointsBecomeAFourConnectedWalk) {
  const KnownMap map = known({"....", "....", "...."});
  PathFollower follower;
  // From (0,0) straight east to (3,0), then south to (3,2).
  ASSERT_EQ(follower.follow({centre(0, 0, 3), centre(3, 0, 3), centre(3, 2, 3)}, kFrame, Cell{0, 0}, Cell{3, 2}, map), "");
  const std::vector<Cell> expected{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}};
  EXPECT_EQ(drive(follower, Cell{0, 0}, map), expected);
}

TEST(PathFollowerTest, ADiagonalSegmentTakesTheXStepFirstAtCorners) {
  const KnownMap map = known({"....", "....", "...."});
  PathFollower follower;
  ASSERT_EQ(follower.follow({centre(0, 0, 3), centre(2, 2, 3)}, kFrame, Cell{0, 0}, Cell{2, 2}, map), "");
  const std::vector<Cell> expected{{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}};
  EXPECT_EQ(drive(follower, Cell{0, 0}, map), expected);
}

TEST(PathFollowerTest, UnderConnectivityEightCornersWithBothSidesKnownFreeAreCutDiagonally) {
  // The same diagonal segment: its walk (0,0) (1,0) (1,1) (2,1) (2,2) turns three corners; with both sides of
  // each known free the robot takes two diagonal moves.
  const KnownMap open = known({"....", "....", "...."});
  PathFollower follower;
  follower.setConnectivity(Connectivity::Eight);
  ASSERT_EQ(follower.follow({centre(0, 0, 3), centre(2, 2, 3)}, kFrame, Cell{0, 0}, Cell{2, 2}, open), "");
  EXPECT_EQ(follower.next(Cell{0, 0}, open), Action::SouthEast);
  EXPECT_EQ(drive(follower, Cell{0, 0}, open), (std::vector<Cell>{{0, 0}, {1, 1}, {2, 2}}));
  // A corner whose other side is an obstacle or unknown is walked round: with (0,1) an obstacle, or unknown, the
  // first corner is walked; the next one, (1,0)-(2,1) beside (2,0) and (1,1), is cut.
  for (const char* side : {"#...", "?..."}) {
    const KnownMap blocked = known({"....", side, "...."});
    ASSERT_EQ(follower.follow({centre(0, 0, 3), centre(2, 2, 3)}, kFrame, Cell{0, 0}, Cell{2, 2}, blocked), "");
    EXPECT_EQ(drive(follower, Cell{0, 0}, blocked), (std::vector<Cell>{{0, 0}, {1, 0}, {2, 1}, {2, 2}})) << side;
  }
  // Under the default connectivity 4 nothing is cut.
  PathFollower four;
  ASSERT_EQ(four.follow({centre(0, 0, 3), centre(2, 2, 3)}, kFrame, Cell{0, 0}, Cell{2, 2}, open), "");
  EXPECT_EQ(drive(four, Cell{0, 0}, open).size(), 5u);
}

TEST(PathFollowerTest, RejectsPathsThroughWallsOffTheMapOrAwayFromTheRobot) {
  const KnownMap map = known({".#..", ".#..", "...."});
  PathFollower follower;
  EXPECT_EQ(follower.follow({}, kFrame, Cell{0, 0}, Cell{3, 0}, map), "the path is empty");
  EXPECT_EQ(follower.follow({centre(0, 0, 3), centre(3, 0, 3)}, kFrame, Cell{0, 0}, Cell{3, 0}, map),
            "the path crosses the obstacle cell (1, 0)");
  EXPECT_EQ(follower.follow({centre(0, 0, 3), MapPoint{0.5, 3.5}}, kFrame, Cell{0, 0}, Cell{3, 0}, map),
            "the path leaves the map at cell (0, -1)");
  EXPECT_EQ(follower.follow({centre(0, 2, 3), centre(3, 2, 3)}, kFrame, Cell{0, 0}, Cell{3, 2}, map),
            "the path does not pass through the robot's cell (0, 0) (it starts at (0, 2))");
  EXPECT_EQ(follower.follow({centre(0, 0, 3), centre(0, 2, 3)}, kFrame, Cell{0, 0}, Cell{3, 0}, map),
            "the path ends at cell (0, 2), not at the goal (3, 0)");
  EXPECT_EQ(follower.follow({centre(0, 0, 3), MapPoint{1e12, 0.5}}, kFrame, Cell{0, 0}, Cell{3, 0}, map)
                .rfind("the path has a pose far off the map (", 0),
            0u);
  // None of them was taken.
  EXPECT_FALSE(follower.next(Cell{0, 0}, map));
  // Unknown cells are fine (the optimistic assumption), and so is an obstacle behind the robot.
  const KnownMap hidden = known({"??..", "#...", "...."});
  EXPECT_EQ(follower.follow({centre(0, 0, 3), centre(3, 0, 3)}, kFrame, Cell{0, 0}, Cell{3, 0}, hidden), "");
  EXPECT_EQ(follower.follow({centre(0, 1, 3), centre(3, 1, 3)}, kFrame, Cell{1, 1}, Cell{3, 1}, hidden), "");
}

TEST(PathFollowerTest, AsksForAReplanWhenTheNextCellTurnsOutBlockedOrTheRobotLeavesThePath) {
  KnownMap map = known({"?...", "....", "...."});
  PathFollower follower;
  ASSERT_EQ(follower.follow({centre(3, 0, 3), centre(0, 0, 3)}, kFrame, Cell{3, 0}, Cell{0, 0}, map), "");
  EXPECT_EQ(follower.next(Cell{3, 0}, map), Action::West);
  EXPECT_EQ(follower.next(Cell{2, 0}, map), Action::West);
  // The robot bumped: same move again.
  EXPECT_EQ(follower.next(Cell{2, 0}, map), Action::West);
  EXPECT_EQ(follower.next(Cell{1, 0}, map), Action::West);
  map.cells[0] = kScanObstacle;  // (0, 0) seen to be a wall
  EXPECT_FALSE(follower.next(Cell{1, 0}, map));
  // A robot off the path gets no move, nor one standing at its end.
  ASSERT_EQ(follower.follow({centre(1, 0, 3), centre(1, 1, 3)}, kFrame, Cell{1, 0}, Cell{1, 1}, map), "");
  EXPECT_FALSE(follower.next(Cell{2, 2}, map));
  EXPECT_EQ(follower.next(Cell{1, 0}, map), Action::South);
  EXPECT_FALSE(follower.next(Cell{1, 1}, map));
  follower.clear();
  EXPECT_FALSE(follower.next(Cell{1, 1}, map));
}

TEST(PathFollowerTest, ThePathMayPassTheRobotMidway) {
  // A re-plan published while the robot moved on: the robot is on the walk, just not at its start.
  const KnownMap map = known({"....", "....", "...."});
  PathFollower follower;
  ASSERT_EQ(follower.follow({centre(0, 2, 3), centre(3, 2, 3)}, kFrame, Cell{2, 2}, Cell{3, 2}, map), "");
  EXPECT_EQ(follower.next(Cell{2, 2}, map), Action::East);
}

}  // namespace
}  // namespace agents
}  // namespace ppp
