// MRPT's wavefront planner (mrpt::nav::PlannerSimple2D::computePath) called directly: why a robot that re-plans
// with it at every step can shuttle between two cells for ever, and two faults of its input checks.
//
// How computePath works, as far as these tests need it. Cells are MRPT's (x, y) indices, y counted from the bottom.
// The origin cell is stamped O, the target cell T. Then whole raster sweeps (y ascending, x ascending, in place) of
// a window that grows by one cell per side each sweep, starting at the two cells' bounding box +-2, never touching
// the map's outer ring. Each sweep visits the cells not yet labelled (free, or "empty"); such a cell with a
// labelled neighbour of the origin's wave takes that neighbour's label plus the step cost, added twice (orthogonal
// neighbours are looked at first, costing 2, then diagonals, costing 3); likewise for the target's wave, counting
// down. The first empty cell in that order that touches both waves is the meeting cell, and the search stops there:
// neither the origin nor the target can be it, and labels are first-touch values, not distances. The path is the
// meeting cell, traced back to the origin and climbed up to the target, each cell at least minStepInReturnedPath
// from the previous point (0: every cell), then the exact target.
#include <gtest/gtest.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/nav/planners/PlannerSimple2D.h>
#include <mrpt/poses/CPose2D.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "grid_map.hpp"
#include "map_picture.hpp"
#include "mrpt_grid_planner.hpp"
#include "ppp_agents/planner_episode.hpp"
#include "ppp_core/segment_walk.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {
namespace planners {
namespace {

using mrpt::math::TPoint2D;
using Path = std::deque<TPoint2D>;

/// MRPT's answer: the path and its notFound flag.
struct Answer {
  Path path;
  bool not_found = true;
};

/// computePath from the point `from` to the point `to` with a robot radius and a minimum step (metres), and MRPT's
/// default obstacle threshold (cells with a probability of being free above 0.5 are free).
Answer computePath(const mrpt::maps::COccupancyGridMap2D& map, TPoint2D from, TPoint2D to, float robot_radius,
                   float min_step) {
  mrpt::nav::PlannerSimple2D planner;
  planner.robotRadius = robot_radius;
  planner.minStepInReturnedPath = min_step;
  Answer answer;
  planner.computePath(map, mrpt::poses::CPose2D(from.x, from.y, 0), mrpt::poses::CPose2D(to.x, to.y, 0), answer.path,
                      answer.not_found);
  return answer;
}

/// A free 7x6 MRPT map of 1 m cells, with the listed cells (MRPT indices) occupied.
mrpt::maps::COccupancyGridMap2D smallMap(const std::vector<std::pair<int, int>>& occupied = {}) {
  mrpt::maps::COccupancyGridMap2D map;
  map.setSize(0, 7, 0, 6, 1.0f, 1.0f);
  for (const auto& [x, y] : occupied) map.setCell(x, y, 0.0f);
  return map;
}

/// The centre of an MRPT cell of a 1 m map.
TPoint2D centre(int x, int y) { return TPoint2D(x + 0.5, y + 0.5); }

void expectPath(const Path& actual, const std::vector<TPoint2D>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    EXPECT_DOUBLE_EQ(actual[i].x, expected[i].x) << "point " << i;
    EXPECT_DOUBLE_EQ(actual[i].y, expected[i].y) << "point " << i;
  }
}

// Robot radius 0 and minimum step 0, so every cell of the path is a point. Target T = (3,3).
// From A = (2,2): the first sweep covers x, y in [1,4]. Row 1: (1,1) = 6 (diagonal of O), (2,1) = 4 (below O),
// (3,1) = 6, (4,1) = 10; row 2: (1,2) = 4. Then (3,2) has O to its west and T above it: the meeting cell.
// From B = (3,2): row 1: (1,1) stays empty, (2,1) = 6, (3,1) = 4, (4,1) = 6; row 2: (1,2) = 12. Then (2,2) has O
// to its east and T diagonally above: the meeting cell.
// A shortest path from either cell is the single step onto T (A is T's diagonal neighbour, B its orthogonal one).
TEST(MrptLivelockTest, TwoNeighboursOfTheTargetAreSentToEachOther) {
  const auto map = smallMap();
  const TPoint2D target = centre(3, 3);
  const Answer from_a = computePath(map, centre(2, 2), target, 0, 0);
  const Answer from_b = computePath(map, centre(3, 2), target, 0, 0);
  ASSERT_FALSE(from_a.not_found);
  ASSERT_FALSE(from_b.not_found);
  expectPath(from_a.path, {centre(3, 2), target});  // A's first step: B
  expectPath(from_b.path, {centre(2, 2), target});  // B's first step: A
  // A robot that takes the first point and asks again goes A, B, A, B, ... and never onto T, next to both.
}

// ---------------------------------------------------------------------------------------------------------------
// The same on a PPP: the bridge's robot, planning with mrpt_planner_node, shuttles between two cells for ever.

/// The PPP (grid y down, row 0 at the top): start S (0,0), goal G (19,19), 1 m per cell.
const std::vector<std::string> kLoopPpp = {
    "S.............#.....",  //
    ".............#......",  //
    ".............#......",  //
    "............#.......",  //
    "...........#........",  //
    "..........#.........",  //
    ".........#..........",  //
    "........#..#........",  //
    ".......#..#.........",  //
    "......#..#..........",  //
    ".....#..#...........",  //
    "....#..#............",  //
    "..#...#.............",  //
    "...#.#..............",  //
    "....#...............",  //
    "....................",  //
    "....................",  //
    "....................",  //
    "....................",  //
    "...................G",  //
};
const MapFrame kPppFrame{20, 20, 1.0};
constexpr int kCellsPerPppCell = 4;  // the mrpt agent's cells_per_ppp_cell: the node plans on 0.25 m cells
constexpr double kInflation = 1;     // the node's ~inflation, in map cells: MRPT's robotRadius 0.25 m
constexpr int kBudget = 300;         // moves per run

/// The node's map of what the robot knows, as the bridge publishes it (every PPP cell as 4x4 map cells,
/// nav_msgs/OccupancyGrid order, row 0 at the bottom) and mrpt_planner_node reads it: unknown cells free (its default
/// ~unknown_is_free) and no inflation in the GridMap (the node hands ~inflation to MRPT as its robot radius).
GridMap nodeMapOf(const agents::KnownMap& known) {
  const MapFrame fine{known.width * kCellsPerPppCell, known.height * kCellsPerPppCell,
                      kPppFrame.resolution / kCellsPerPppCell};
  std::vector<std::int8_t> data(static_cast<std::size_t>(fine.width * fine.height));
  for (int y = 0; y < fine.height; ++y) {
    for (int x = 0; x < fine.width; ++x) {
      data[fine.mapIndex(Cell{x, y})] = known.at(Cell{x / kCellsPerPppCell, y / kCellsPerPppCell});
    }
  }
  return GridMap(fine.width, fine.height, fine.resolution, data, true);
}

/// The map cell the node plans from for a PPP cell: the one holding its centre (GridMap::cellOf). The centre is a
/// corner of four map cells and a point on a boundary belongs to the cell of larger grid index: (4x+2, 4y+2).
Cell nodeCellOf(const GridMap& map, Cell ppp_cell) {
  return map.cellOf(MapPoint{kPppFrame.centreX(ppp_cell), kPppFrame.centreY(ppp_cell)});
}

/// mrpt_planner_node answering the bridge's request at each step (PlannerNode::serve): the last plan again when
/// the robot moved on along it and the map is unchanged (the plan passes the robot's map cell), else a new plan.
class NodeModel {
 public:
  std::vector<MapPoint> answer(const agents::KnownMap& known, Cell robot, Cell goal) {
    const GridMap map = nodeMapOf(known);
    const Cell from = nodeCellOf(map, robot);
    const bool keeps = !plan_.empty() && !(from == from_) && known.cells == known_ && map.pathPasses(plan_, from);
    if (!keeps) {
      plan_ = planner_.plan(map, from, nodeCellOf(map, goal));
      from_ = from;
      known_ = known.cells;
    }
    return plan_;
  }

 private:
  MrptGridPlanner planner_{kInflation};
  std::vector<MapPoint> plan_;
  Cell from_{-1, -1};
  std::vector<std::int8_t> known_;
};

/// The robot's cell at one step and what it knew there (after that step's scan).
struct Visit {
  Cell robot;
  std::vector<std::int8_t> known;
};

/// A run played as the simulator, the bridge (PlannerEpisode, 5x5 line-of-sight scans into a full memory, a plan
/// request every step, the robot one PPP cell along the path) and the node play it.
struct Played {
  std::vector<Visit> visits;  // one per move
  Cell end;                   // where the robot is after its last move
  std::string failure;        // why it stopped before its budget, if it did (the bridge's verdict)
};

Played play() {
  const Grid grid = test::pictureGrid(kLoopPpp);
  const Cell start = test::markedCell(kLoopPpp, 'S');
  const Cell goal = test::markedCell(kLoopPpp, 'G');
  const SensorModel sensor(SensorOptions{2, 0.0});
  agents::PlannerEpisode episode;
  episode.start(agents::EpisodeInfo{grid.width(), grid.height(), start, goal, 0, nullptr}, nullptr, 0,
                kPppFrame.resolution);
  NodeModel node;
  std::vector<MapPoint> following;  // the plan the bridge follows
  Played run{{}, start, ""};
  Cell& robot = run.end;
  for (int step = 0; step < kBudget && !(robot == goal); ++step) {
    std::vector<std::int8_t> window(static_cast<std::size_t>(sensor.side() * sensor.side()));
    sensor.scan(grid, robot, 0, step, window.data());
    episode.observe(Scan(2, window, robot, goal, false, step));
    run.visits.push_back(Visit{robot, episode.known().cells});
    const std::vector<MapPoint> plan = node.answer(episode.known(), robot, goal);
    // The bridge goes on along the plan it follows when the node sends it again (PlannerBridge::followPath).
    std::optional<Action> move;
    if (!plan.empty() && plan.size() == following.size() &&
        std::equal(plan.begin(), plan.end(), following.begin(),
                   [](const MapPoint& a, const MapPoint& b) { return a.x == b.x && a.y == b.y; })) {
      move = episode.next(robot);
    }
    if (!move) {
      const agents::Answer answer = episode.answer(plan, robot);
      if (answer.verdict != agents::AnswerVerdict::Move) {
        run.failure = answer.detail;
        break;
      }
      move = answer.action;
      following = plan;
    }
    const Cell next = target(robot, *move);
    if (grid.isFree(next)) robot = next;
  }
  return run;
}

/// The first index i from which the run shuttles between two cells on unchanged knowledge: visits i and i+2 at one
/// cell, i+1 at another, all three knowing the same. -1 when there is none.
int shuttleStart(const std::vector<Visit>& visits) {
  for (std::size_t i = 0; i + 2 < visits.size(); ++i) {
    const Visit& a = visits[i];
    const Visit& b = visits[i + 1];
    const Visit& again = visits[i + 2];
    if (again.robot == a.robot && !(b.robot == a.robot) && b.known == a.known && again.known == a.known) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

/// The first PPP cell other than `robot` that the path from `origin` through `path` enters, walked as the bridge
/// walks a plan (walkMapSegment in the PPP's frame); {-1, -1} when it never leaves the robot's cell.
Cell firstCellAfter(Cell robot, TPoint2D origin, const Path& path) {
  TPoint2D from = origin;
  for (const TPoint2D& to : path) {
    for (const Cell c : walkMapSegment(kPppFrame, from.x, from.y, to.x, to.y)) {
      if (!(c == robot)) return c;
    }
    from = to;
  }
  return Cell{-1, -1};
}

// The bridge's run on the PPP above, replayed in-process: from step 47 the robot shuttles between (3,12) and (3,11)
// (moves North, South, North, ...) to the end of its budget, knowing nothing new. MRPT's own answers on that
// knowledge explain it: from (3,12) its route goes west round the lower wall, first north through (3,11) since
// (2,12) is a wall; from (3,11) it goes east between the walls, first south through (3,12) since (4,11) is a wall.
// Either route alone leads to the goal; MRPT picks its route by where its two waves first meet, so the two cells
// pick different ones. The node does not keep its last plan either: the plan from one cell passes through the
// other's PPP cell but not through the map cell the node plans from there.
TEST(MrptLivelockTest, RobotShuttlesBetweenTwoCellsOnTheLoopPpp) {
  const Played run = play();
  ASSERT_EQ(run.failure, "");
  ASSERT_EQ(run.visits.size(), static_cast<std::size_t>(kBudget));  // the budget ran out...
  EXPECT_FALSE(run.end == test::markedCell(kLoopPpp, 'G'));       // ...off the goal
  const int start = shuttleStart(run.visits);
  ASSERT_GE(start, 0) << "no two-cell shuttle on unchanged knowledge";
  EXPECT_EQ(start, 47);
  const Visit& a = run.visits[start];
  const Visit& b = run.visits[start + 1];
  EXPECT_EQ(cellText(a.robot), "(3, 12)");
  EXPECT_EQ(cellText(b.robot), "(3, 11)");
  EXPECT_EQ(std::abs(a.robot.x - b.robot.x) + std::abs(a.robot.y - b.robot.y), 1) << "not neighbours";
  EXPECT_TRUE(a.known == b.known);
  // To the end of the budget: A, B, A, B, ...
  for (std::size_t i = start + 2; i < run.visits.size(); ++i) {
    EXPECT_TRUE(run.visits[i].robot == run.visits[i - 2].robot) << "step " << i;
  }

  // MRPT on that knowledge, as MrptGridPlanner calls it: 0.25 m cells, robotRadius one cell, its default
  // minStepInReturnedPath (0.4 m), from the map cell holding the robot's PPP cell centre to the goal's.
  agents::KnownMap known{kPppFrame.width, kPppFrame.height, a.known};
  const GridMap map = nodeMapOf(known);
  const auto grid = mrptGridOf(map);
  const Cell goal_cell = nodeCellOf(map, test::markedCell(kLoopPpp, 'G'));
  const MapPoint goal = map.centre(goal_cell);
  const auto robot_radius = static_cast<float>(kInflation * map.frame().resolution);
  const float min_step = mrpt::nav::PlannerSimple2D().minStepInReturnedPath;
  for (const auto& [here, there] : {std::pair<Cell, Cell>{a.robot, b.robot}, {b.robot, a.robot}}) {
    const MapPoint from = map.centre(nodeCellOf(map, here));
    const Answer answer =
        computePath(grid, TPoint2D(from.x, from.y), TPoint2D(goal.x, goal.y), robot_radius, min_step);
    ASSERT_FALSE(answer.not_found) << "from " << cellText(here);
    EXPECT_EQ(cellText(firstCellAfter(here, TPoint2D(from.x, from.y), answer.path)), cellText(there))
        << "from " << cellText(here);
  }
  // Why the node plans anew at each cell: its plan from one cell misses the map cell it plans from at the other.
  const MrptGridPlanner planner(kInflation);
  EXPECT_FALSE(map.pathPasses(planner.plan(map, nodeCellOf(map, a.robot), goal_cell), nodeCellOf(map, b.robot)));
  EXPECT_FALSE(map.pathPasses(planner.plan(map, nodeCellOf(map, b.robot), goal_cell), nodeCellOf(map, a.robot)));
}

// ---------------------------------------------------------------------------------------------------------------
// The input checks.

// computePath refuses a call only when the origin is off the map and the target on it: its check is
// !(origin_in || !target_in). With the target off the map it stamps T at an index it never checks. A target just
// past xMax has x index 7 == size_x, which lands on (0, y+1) inside the grid's buffer (so this call writes nothing
// out of bounds), and the search runs to that cell: from O = (2,2) the first cell touching both O and the stamped
// cell (0,3) is (1,2), and the path ends at the requested point, off the map. Its header promises notFound instead.
TEST(MrptLivelockTest, TargetJustPastTheRightEdgeIsPlannedTo) {
  const auto map = smallMap();
  const TPoint2D off_map(7.5, 2.5);
  ASSERT_GE(off_map.x, map.getXMax());
  // Where the stamp goes: inside the buffer, on the next row's first cell.
  const int index = map.x2idx(off_map.x) + static_cast<int>(map.getSizeX()) * map.y2idx(off_map.y);
  ASSERT_EQ(index, 0 + 7 * 3);
  ASSERT_LT(index, static_cast<int>(map.getSizeX() * map.getSizeY()));
  const Answer answer = computePath(map, centre(2, 2), off_map, 0, 0);
  EXPECT_FALSE(answer.not_found);
  expectPath(answer.path, {centre(1, 2), off_map});
}

// MrptGridPlanner never hands MRPT such a goal: a goal off the map is no path.
TEST(MrptLivelockTest, WrapperRefusesAGoalOffTheMap) {
  const GridMap map = test::mapPicture({".......", ".......", ".......", ".......", ".......", "......."});
  const MrptGridPlanner planner(0);
  ASSERT_FALSE(planner.plan(map, Cell{2, 3}, Cell{6, 3}).empty());  // the last column is fine
  EXPECT_TRUE(planner.plan(map, Cell{2, 3}, Cell{7, 3}).empty());   // centre (7.5, 2.5), as in the test above
  EXPECT_TRUE(planner.plan(map, Cell{2, 3}, Cell{3, -1}).empty());
}

// notFound is "no wave grew in the last sweep". O = (3,2), T = (3,3) above it, (2..4, 1) occupied below O. The
// first sweep's first empty cell with a labelled neighbour is (2,2): O to its east and T diagonally above. It touches
// both waves, so the search stops before any cell was labelled, and notFound says no path for two neighbours.
TEST(MrptLivelockTest, NeighboursBehindAWallAreReportedUnreachable) {
  const auto map = smallMap({{2, 1}, {3, 1}, {4, 1}});
  const Answer answer = computePath(map, centre(3, 2), centre(3, 3), 0, 0);
  EXPECT_TRUE(answer.not_found);
  EXPECT_TRUE(answer.path.empty());
  // Without the wall the first sweep labels row 1 first, and the same pair is found.
  EXPECT_FALSE(computePath(smallMap(), centre(3, 2), centre(3, 3), 0, 0).not_found);
}

}  // namespace
}  // namespace planners
}  // namespace ppp
