// The agent node's message handling without a master: batched play equals in-process play, episodes missing
// from a batch are finished, and malformed scans are answered with the rejected action, never a crash.
#include "ppp_agents/protocol/batch_responder.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "ppp_core/rng.hpp"
#include "ppp_core/window_mask.hpp"
#include "scan_batch_builder.hpp"
#include "test_world.hpp"

namespace ppp {
namespace agents {
namespace {

using protocol::BatchResponder;
using protocol::kRejectedAction;

using test::config;
using test::world;

const test::World kWorld = world({
    "S...#...",
    ".##.#.#.",
    ".#..#.#.",
    ".#.##.#.",
    ".#....#G",
});

/// One episode played through batches, with the move model of test::runEpisode.
struct Played {
  std::uint32_t id;
  std::uint64_t seed;
  Cell position;
  bool bumped = false;
  int steps = 0;
  test::Outcome outcome;
  bool done = false;
};

/// The step-`step` scan of an episode on kWorld, as the simulator sends it.
test::TestScan scanOf(const Played& p, const SensorModel& sensor, bool prior_map) {
  test::TestScan m;
  m.episode = p.id;
  m.step = p.steps;
  m.position = p.position;
  m.bumped = p.bumped;
  std::vector<std::int8_t> cells(static_cast<std::size_t>(sensor.side() * sensor.side()));
  sensor.scan(kWorld.grid, p.position, deriveSeed(p.seed, {1}), p.steps, cells.data());
  m.window = true;
  packWindow(cells.data(), sensor.options().range, m.free_cells.data(), m.obstacle_cells.data());
  if (p.steps == 0) {
    protocol::EpisodeStart start;
    start.width = kWorld.grid.width();
    start.height = kWorld.grid.height();
    start.start = kWorld.start;
    start.goal = kWorld.goal;
    start.agent_seed = p.seed;
    if (prior_map) {
      for (int i = 0; i < kWorld.grid.size(); ++i) {
        start.prior_map.push_back(kWorld.grid.isObstacle(kWorld.grid.cellAt(i)) ? kScanObstacle : kScanFree);
      }
    }
    m.start = start;
  }
  return m;
}

/// Plays `count` episodes (seeds 100, 101, ...) through one responder, all in lockstep batches, in id order
/// or (`reorder`) in reverse id order every other batch.
std::vector<test::Outcome> playBatched(const AgentConfig& c, int count, std::size_t* most_active,
                                       bool reorder = false) {
  BatchResponder responder(c);
  const SensorModel sensor(SensorOptions{2, c.sensor_noise});
  std::vector<Played> episodes;
  for (int i = 0; i < count; ++i) {
    Played p{static_cast<std::uint32_t>(1000 + 7 * i), static_cast<std::uint64_t>(100 + i), kWorld.start};
    p.outcome.path.push_back(p.position);
    episodes.push_back(p);
  }
  *most_active = 0;
  for (std::uint32_t batch_number = 1;; ++batch_number) {
    std::vector<test::TestScan> scans;
    std::vector<Played*> in_batch;
    for (std::size_t k = 0; k < episodes.size(); ++k) {
      Played& p = episodes[reorder && batch_number % 2 == 1 ? episodes.size() - 1 - k : k];
      if (p.done) continue;
      scans.push_back(scanOf(p, sensor, c.type == "astar"));
      // The simulator sends no window to agents that never read it.
      if (!readsScanWindow(c)) scans.back().window = false;
      in_batch.push_back(&p);
    }
    ppp_msgs::ScanBatch batch = test::packBatch(batch_number, sensor.options().range, scans);
    batch.agent = c.name;
    const ppp_msgs::MoveBatch moves = responder.answer(batch);
    // Episodes that ended in the previous round were finished by this batch.
    EXPECT_EQ(responder.active(), in_batch.size());
    *most_active = std::max(*most_active, responder.active());
    if (in_batch.empty()) break;
    EXPECT_EQ(moves.agent, c.name);
    EXPECT_EQ(moves.batch, batch_number);
    EXPECT_EQ(moves.actions.size(), in_batch.size());
    for (std::size_t i = 0; i < in_batch.size(); ++i) {
      Played& p = *in_batch[i];
      EXPECT_EQ(moves.episodes[i], p.id);
      EXPECT_EQ(moves.steps[i], static_cast<std::uint32_t>(p.steps));
      EXPECT_TRUE(isAction(moves.actions[i])) << int(moves.actions[i]);
      const Action action = static_cast<Action>(moves.actions[i]);
      ++p.steps;
      p.outcome.steps = p.steps;
      p.bumped = false;
      const Cell next = target(p.position, action);
      if (action != Action::Stay) {
        if (kWorld.grid.isFree(next)) {
          p.position = next;
          ++p.outcome.moves;
          p.outcome.path.push_back(next);
        } else {
          p.bumped = true;
          ++p.outcome.bumps;
        }
      }
      p.outcome.passed = p.position == kWorld.goal;
      p.done = p.outcome.passed || p.steps >= 300;
    }
  }
  EXPECT_TRUE(responder.rejections().empty());
  std::vector<test::Outcome> outcomes;
  for (const Played& p : episodes) outcomes.push_back(p.outcome);
  return outcomes;
}

TEST(BatchResponderTest, BatchedPlayEqualsInProcessPlayForEveryAgent) {
  for (const std::string& type : agentTypeNames()) {
    for (const AgentConfig& c : {config(type), config(type, 3), config(type, 0, 0.1)}) {
      // Scans normally come in id order (the responder walks its episodes along); any order must work.
      for (bool reorder : {false, true}) {
        std::size_t most_active = 0;
        const auto batched = playBatched(c, 6, &most_active, reorder);
        EXPECT_EQ(most_active, 6u);
        auto agent = makeAgent(c);
        for (int i = 0; i < 6; ++i) {
          const auto expected = test::runEpisode(*agent, kWorld, 100 + i, c.sensor_noise, 300, type == "astar");
          EXPECT_EQ(batched[i].passed, expected.passed) << type << " episode " << i << " reorder " << reorder;
          EXPECT_EQ(batched[i].steps, expected.steps) << type << " episode " << i << " reorder " << reorder;
          EXPECT_EQ(batched[i].bumps, expected.bumps) << type << " episode " << i << " reorder " << reorder;
          EXPECT_EQ(batched[i].path, expected.path) << type << " episode " << i << " reorder " << reorder;
        }
      }
    }
  }
}

/// A well-formed step-0 scan of episode `id` on kWorld, with its EpisodeStart.
test::TestScan startScan(std::uint32_t id, bool prior_map = false) {
  Played p{id, 5, kWorld.start};
  return scanOf(p, SensorModel(SensorOptions{}), prior_map);
}

/// `scan` at a later step, without its EpisodeStart.
test::TestScan later(test::TestScan scan, int step) {
  scan.step = step;
  scan.start.reset();
  return scan;
}

ppp_msgs::ScanBatch batchOf(const std::vector<test::TestScan>& scans, int range = 2) {
  return test::packBatch(9, range, scans);
}

TEST(BatchResponderTest, MalformedScansAndStartsAreRejectedOneByOne) {
  BatchResponder responder(config("astar"));
  const test::TestScan good = startScan(1, true);
  test::TestScan short_map = startScan(3, true);
  short_map.start->prior_map.pop_back();
  test::TestScan bad_map_value = startScan(4, true);
  bad_map_value.start->prior_map[3] = 7;
  test::TestScan no_map = startScan(5, false);  // astar needs its prior map
  const test::TestScan never_started = later(startScan(6, true), 3);
  test::TestScan off_grid = startScan(7, true);
  off_grid.position.x = 99;
  test::TestScan zero_size = startScan(8, true);
  zero_size.start->width = 0;
  test::TestScan goal_off_grid = startScan(2, true);
  goal_off_grid.start->goal.y = -1;
  const test::TestScan duplicate = later(good, 0);

  const auto moves = responder.answer(batchOf({good, goal_off_grid, short_map, bad_map_value, no_map,
                                               never_started, off_grid, zero_size, duplicate}));
  ASSERT_EQ(moves.actions.size(), 9u);
  EXPECT_EQ(moves.batch, 9u);
  EXPECT_TRUE(isAction(moves.actions[0]));
  const std::vector<std::uint32_t> episodes{1, 2, 3, 4, 5, 6, 7, 8, 1};
  EXPECT_EQ(moves.episodes, episodes);
  for (std::size_t i = 1; i < moves.actions.size(); ++i) EXPECT_EQ(moves.actions[i], kRejectedAction) << i;
  EXPECT_EQ(responder.active(), 1u);  // only the good episode survives its duplicate
  const std::map<std::string, long> expected{{"goal", 1},     {"prior_map", 3}, {"episode", 1},
                                             {"position", 1}, {"size", 1},      {"duplicate", 1}};
  EXPECT_EQ(responder.rejections(), expected);

  // The good episode goes on; a rejected one stays rejected.
  const auto again = responder.answer(batchOf({later(good, 1), later(short_map, 1)}));
  EXPECT_TRUE(isAction(again.actions[0]));
  EXPECT_EQ(again.actions[1], kRejectedAction);
}

TEST(BatchResponderTest, AMalformedBatchIsRejectedWhole) {
  BatchResponder responder(config("explorer"));
  const test::TestScan one = startScan(1);
  const test::TestScan two = startScan(2);

  ppp_msgs::ScanBatch short_cells = batchOf({one, two});
  short_cells.free_cells.pop_back();
  ppp_msgs::ScanBatch short_steps = batchOf({one, two});
  short_steps.steps.pop_back();
  const ppp_msgs::ScanBatch bad_range = batchOf({one, two}, 0);
  for (const ppp_msgs::ScanBatch& bad : {short_cells, short_steps, bad_range}) {
    const auto moves = responder.answer(bad);
    ASSERT_EQ(moves.actions.size(), 2u);
    EXPECT_EQ(moves.actions[0], kRejectedAction);
    EXPECT_EQ(moves.actions[1], kRejectedAction);
    EXPECT_EQ(moves.episodes, bad.episodes);
  }
  const std::map<std::string, long> expected{{"cells", 2}, {"batch", 2}, {"range", 2}};
  EXPECT_EQ(responder.rejections(), expected);
  EXPECT_EQ(responder.active(), 0u);

  // A random agent reads no window, so a batch without cells is well formed for it (and only for it).
  BatchResponder random(config("random"));
  ppp_msgs::ScanBatch windowless = batchOf({one, two});
  windowless.free_cells.clear();
  windowless.obstacle_cells.clear();
  const auto moves = random.answer(windowless);
  EXPECT_TRUE(isAction(moves.actions[0]) && isAction(moves.actions[1]));
  EXPECT_TRUE(random.rejections().empty());
  EXPECT_EQ(responder.answer(windowless).actions[0], kRejectedAction);
}

// Found by the scan_batch fuzz target (UBSan): the responder fetches the memory of the agents a few scans ahead
// before their positions are checked, and an explorer's memory computed x - reach for x = INT_MIN (a signed
// overflow) and addressed rows off the map. Such a scan is rejected, the others answered.
TEST(BatchResponderTest, PositionsFarOffTheMapAreRejectedWithoutTouchingMemory) {
  BatchResponder responder(config("explorer"));
  responder.answer(batchOf({startScan(1), startScan(2), startScan(3), startScan(4)}));
  std::vector<test::TestScan> next{later(startScan(1), 1), later(startScan(2), 1), later(startScan(3), 1),
                                   later(startScan(4), 1)};
  next[2].position = Cell{std::numeric_limits<int>::min(), std::numeric_limits<int>::max()};
  next[3].position = Cell{std::numeric_limits<int>::max(), std::numeric_limits<int>::min()};
  const auto moves = responder.answer(batchOf(next));
  ASSERT_EQ(moves.actions.size(), 4u);
  EXPECT_TRUE(isAction(moves.actions[0]) && isAction(moves.actions[1]));
  EXPECT_EQ(moves.actions[2], kRejectedAction);
  EXPECT_EQ(moves.actions[3], kRejectedAction);
  EXPECT_EQ(responder.rejections(), (std::map<std::string, long>{{"position", 2}}));
}

// Found by the scan_batch fuzz target (UBSan): an episode id restarted with a start its agent refuses (astar
// without a prior map) lost its agent while the responder still held a pointer to it, which the prefetch of the
// batch's first scan followed. The refused restart ends that episode, the others play on, the id can start again.
TEST(BatchResponderTest, ARefusedRestartEndsTheEpisodeAndTheOthersPlayOn) {
  BatchResponder responder(config("astar"));
  responder.answer(batchOf({startScan(1, true), startScan(2, true), startScan(3, true)}));
  const auto moves =
      responder.answer(batchOf({later(startScan(1, true), 1), later(startScan(2, true), 1), startScan(3, false)}));
  ASSERT_EQ(moves.actions.size(), 3u);
  EXPECT_TRUE(isAction(moves.actions[0]) && isAction(moves.actions[1]));
  EXPECT_EQ(moves.actions[2], kRejectedAction);
  EXPECT_EQ(responder.rejections(), (std::map<std::string, long>{{"prior_map", 1}}));
  EXPECT_EQ(responder.active(), 2u);
  const auto again =
      responder.answer(batchOf({later(startScan(1, true), 2), later(startScan(2, true), 2), startScan(3, true)}));
  for (std::uint8_t action : again.actions) EXPECT_TRUE(isAction(action));
  EXPECT_EQ(responder.active(), 3u);
}

TEST(BatchResponderTest, EpisodesMissingFromABatchAreFinishedAndIdsCanRestart) {
  BatchResponder responder(config("explorer"));
  responder.answer(batchOf({startScan(1), startScan(2), startScan(3)}));
  EXPECT_EQ(responder.active(), 3u);
  responder.answer(batchOf({later(startScan(2), 1)}));
  EXPECT_EQ(responder.active(), 1u);
  // Episode 1 is over: a later scan of it is rejected, a new EpisodeStart starts it afresh.
  EXPECT_EQ(responder.answer(batchOf({later(startScan(1), 1), later(startScan(2), 2)})).actions[0],
            kRejectedAction);
  EXPECT_TRUE(isAction(responder.answer(batchOf({startScan(1)})).actions[0]));
  EXPECT_EQ(responder.active(), 1u);
  EXPECT_TRUE(responder.answer(batchOf({})).actions.empty());
  EXPECT_EQ(responder.active(), 0u);
}

}  // namespace
}  // namespace agents
}  // namespace ppp
