// PlannerEpisode: what the bridge's robot knows and the verdicts on a planner's answers, without ROS.
// The map is 4x3 at 1 m per cell; a cell's centre in the map frame is (x + 0.5, 2 - y + 0.5).
#include "ppp_agents/planner_episode.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "ppp_core/diagnosis.hpp"
#include "test_world.hpp"

namespace ppp {
namespace agents {
namespace {

const test::World kWorld = test::world({
    "S#..",
    ".#..",
    "...G",
});

MapPoint centre(int x, int y) { return MapPoint{x + 0.5, 2 - y + 0.5}; }

EpisodeInfo info() { return EpisodeInfo{4, 3, kWorld.start, kWorld.goal, 7, nullptr}; }

/// The range-1 scan of the true map at `robot`.
Scan scanAt(Cell robot) {
  static const SensorModel sensor(SensorOptions{1, 0.0});
  std::vector<std::int8_t> cells(9);
  sensor.scan(kWorld.grid, robot, 0, 0, cells.data());
  return Scan(1, cells, robot, kWorld.goal, false, 0);
}

TEST(PlannerEpisodeTest, WithThePriorMapTheRobotKnowsEverythingAndJudgesAnswersOnIt) {
  PlannerEpisode episode;
  episode.start(info(), &kWorld.grid, 0, 1.0);
  EXPECT_EQ(episode.known().at(Cell{1, 0}), kScanObstacle);
  EXPECT_EQ(episode.known().at(Cell{3, 0}), kScanFree);
  const Cell robot{0, 0};
  EXPECT_FALSE(episode.next(robot));  // no path yet: ask the planner
  // Straight through the wall: not a fitting answer, and judged invalid.
  const std::vector<MapPoint> through{centre(0, 0), centre(3, 0), centre(3, 2)};
  EXPECT_FALSE(episode.fits(through, robot));
  const Answer bad = episode.answer(through, robot);
  EXPECT_EQ(bad.verdict, AnswerVerdict::InvalidPath);
  EXPECT_EQ(bad.detail, "the path crosses the obstacle cell (1, 0)");
  // An empty answer is the planner's "no path".
  EXPECT_TRUE(episode.fits({}, robot));
  EXPECT_EQ(episode.answer({}, robot).verdict, AnswerVerdict::NoPath);
  // Around the wall: followed.
  const std::vector<MapPoint> around{centre(0, 0), centre(0, 2), centre(3, 2)};
  EXPECT_TRUE(episode.fits(around, robot));
  const Answer good = episode.answer(around, robot);
  EXPECT_EQ(good.verdict, AnswerVerdict::Move);
  EXPECT_EQ(good.action, Action::South);
  EXPECT_EQ(episode.next(Cell{0, 1}), Action::South);
}

TEST(PlannerEpisodeTest, WithoutItTheRobotLearnsFromScansAndReplansWhenAWallAppears) {
  PlannerEpisode episode;
  episode.start(info(), nullptr, 0, 1.0);
  EXPECT_EQ(episode.known().at(Cell{3, 0}), kScanUnknown);
  // The first scan shows the wall next to the start; the far side stays unknown.
  episode.observe(scanAt(Cell{0, 0}));
  EXPECT_EQ(episode.known().at(Cell{1, 0}), kScanObstacle);
  EXPECT_EQ(episode.known().at(Cell{3, 0}), kScanUnknown);
  const std::vector<MapPoint> through{centre(0, 0), centre(3, 0), centre(3, 2)};
  EXPECT_EQ(episode.answer(through, Cell{0, 0}).verdict, AnswerVerdict::InvalidPath);
  // An unasked path is followed when usable and ignored when not.
  episode.offer(through, Cell{0, 0});
  EXPECT_FALSE(episode.next(Cell{0, 0}));
  episode.offer({centre(0, 0), centre(0, 2), centre(3, 2)}, Cell{0, 0});
  EXPECT_EQ(episode.next(Cell{0, 0}), Action::South);
  // A new episode forgets the map and the path.
  episode.start(info(), nullptr, 0, 1.0);
  EXPECT_EQ(episode.known().at(Cell{1, 0}), kScanUnknown);
  EXPECT_FALSE(episode.next(Cell{0, 0}));
}

TEST(PlannerEpisodeTest, ObserveSaysWhetherWhatTheRobotKnowsChanged) {
  PlannerEpisode episode;
  episode.start(info(), nullptr, 0, 1.0);
  EXPECT_TRUE(episode.observe(scanAt(Cell{0, 0})));   // the first scan: (0,0), (1,0), (0,1), (1,1) become known
  EXPECT_FALSE(episode.observe(scanAt(Cell{0, 0})));  // the same scan again
  EXPECT_TRUE(episode.observe(scanAt(Cell{0, 1})));   // one row down: row 2 appears
  EXPECT_FALSE(episode.observe(scanAt(Cell{0, 0})));  // back up: (0,0)'s window is all known already
  // A 1x1 memory forgets the cells it leaves: the same move changes the map every time.
  episode.start(info(), nullptr, 1, 1.0);
  EXPECT_TRUE(episode.observe(scanAt(Cell{0, 0})));
  EXPECT_TRUE(episode.observe(scanAt(Cell{0, 1})));
  EXPECT_TRUE(episode.observe(scanAt(Cell{0, 0})));
  // Given the true map, the robot has nothing to learn.
  episode.start(info(), &kWorld.grid, 0, 1.0);
  EXPECT_FALSE(episode.observe(scanAt(Cell{0, 0})));
}

TEST(PlannerEpisodeTest, AStepNeedsNoRequestOnlyWhenTheRuleSaysSo) {
  BridgeOptions every;
  BridgeOptions change;
  change.plan_requests = kPlanRequestsOnChange;
  BridgeOptions blocked;
  blocked.plan_requests = kPlanRequestsOnBlocked;
  BridgeOptions free_running = blocked;
  free_running.lockstep = false;
  // On the prior map nothing new is ever seen: down the first column, along the bottom row.
  PlannerEpisode known;
  known.start(info(), &kWorld.grid, 0, 1.0);
  known.observe(scanAt(Cell{0, 0}));
  EXPECT_FALSE(known.moveWithoutRequest(change));  // no path yet
  ASSERT_EQ(known.answer({centre(0, 0), centre(0, 2), centre(3, 2)}, Cell{0, 0}).action, Action::South);
  known.observe(scanAt(Cell{0, 1}));
  EXPECT_EQ(known.moveWithoutRequest(change), Action::South);
  known.observe(scanAt(Cell{0, 2}));
  EXPECT_EQ(known.moveWithoutRequest(blocked), Action::East);
  EXPECT_FALSE(known.moveWithoutRequest(every));
  EXPECT_FALSE(known.moveWithoutRequest(free_running));
  known.observe(scanAt(Cell{0, 2}));  // a bump: it stayed
  EXPECT_FALSE(known.moveWithoutRequest(blocked));
  // From its memory: the scan at (0, 1) shows row 2, a change that on_change asks about and on_blocked does not.
  PlannerEpisode learning;
  learning.start(info(), nullptr, 0, 1.0);
  learning.observe(scanAt(Cell{0, 0}));
  learning.answer({centre(0, 0), centre(0, 2), centre(3, 2)}, Cell{0, 0});
  ASSERT_TRUE(learning.observe(scanAt(Cell{0, 1})));
  EXPECT_FALSE(learning.moveWithoutRequest(change));
  EXPECT_EQ(learning.moveWithoutRequest(blocked), Action::South);
}

TEST(PlannerEpisodeTest, TheStateDigestIsEqualExactlyWhenTheWholeDecisionStateIs) {
  const std::vector<MapPoint> around{centre(0, 0), centre(0, 2), centre(3, 2)};
  const auto played = [&](const std::vector<Cell>& cells) {
    PlannerEpisode episode;
    episode.start(info(), nullptr, 0, 1.0);
    for (const Cell c : cells) episode.observe(scanAt(c));
    return episode;
  };
  // Two episodes that saw the same scans from the same cells and follow nothing are in the same state.
  PlannerEpisode a = played({{0, 0}, {0, 1}});
  PlannerEpisode b = played({{0, 0}, {0, 1}});
  EXPECT_EQ(a.stateDigest({}), b.stateDigest({}));
  EXPECT_NE(a.stateDigest({}), 0u);
  // The last answer's waypoints are part of it.
  EXPECT_NE(a.stateDigest({}), a.stateDigest(around));
  // So is the path followed and the robot's place on it.
  const std::uint64_t before = b.stateDigest(around);
  ASSERT_EQ(b.answer(around, Cell{0, 1}).verdict, AnswerVerdict::Move);
  EXPECT_NE(b.stateDigest(around), before);
  // The same scans seen, the same cell, nothing new in the last scan: only the cell before differs.
  EXPECT_NE(played({{0, 0}, {0, 1}, {0, 1}}).stateDigest({}), played({{0, 1}, {0, 0}, {0, 1}}).stateDigest({}));
  // The same cell, the same cell before, nothing new in the last scan: only what the robot knows differs (the
  // first has also seen the goal's corner from (2, 2)).
  EXPECT_NE(played({{2, 2}, {0, 0}, {0, 0}}).stateDigest({}), played({{0, 0}, {0, 0}}).stateDigest({}));
  // The step number is not part of the state: a robot that stayed a step longer is where it was.
  EXPECT_EQ(played({{0, 0}, {0, 0}, {0, 0}}).stateDigest({}), played({{0, 0}, {0, 0}}).stateDigest({}));
}

TEST(PlannerEpisodeTest, ANoPathIsAMissedRouteWhenTheGivenMapHadOneForTheRobotsBody) {
  // Nothing known yet: unknown cells count as passable, so "no path" missed the route.
  PlannerEpisode blind;
  blind.start(info(), nullptr, 0, 1.0);
  EXPECT_STREQ(blind.noPathKind(Cell{0, 0}, 0), diagnosis::kMissedRoute);
  // The true map (column 1 blocked but for its bottom cell): a point robot has the route along the bottom row.
  PlannerEpisode known;
  known.start(info(), &kWorld.grid, 0, 1.0);
  EXPECT_STREQ(known.noPathKind(Cell{0, 0}, 0), diagnosis::kMissedRoute);
  // A disc of radius 1 cell overlaps the wall from every cell next to it, the robot's own included: no route.
  EXPECT_STREQ(known.noPathKind(Cell{0, 0}, 1.0), diagnosis::kNoRoute);
  // A map that walls the robot in (what a noisy scan may report) has no route either.
  const test::World walled = test::world({
      "S#..",
      "##..",
      "...G",
  });
  PlannerEpisode boxed;
  boxed.start(info(), &walled.grid, 0, 1.0);
  EXPECT_STREQ(boxed.noPathKind(Cell{0, 0}, 0), diagnosis::kNoRoute);
}

}  // namespace
}  // namespace agents
}  // namespace ppp
