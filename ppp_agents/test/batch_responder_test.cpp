// The agent node's message handling without a master: batched play equals in-process play, episodes missing
// from a batch are finished, and malformed scans are answered with the rejected action, never a crash.
#include "batch_responder.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "ppp_core/rng.hpp"
#include "test_world.hpp"

namespace ppp {
namespace agents {
namespace {

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

ppp_msgs::GridCell cell(Cell c) {
  ppp_msgs::GridCell m;
  m.x = c.x;
  m.y = c.y;
  return m;
}

/// The step-`step` scan of an episode on kWorld, as the simulator sends it.
ppp_msgs::EpisodeScan scanMessage(const Played& p, const SensorModel& sensor, bool prior_map) {
  ppp_msgs::EpisodeScan m;
  m.episode = p.id;
  m.step = static_cast<std::uint32_t>(p.steps);
  m.position = cell(p.position);
  m.goal = cell(kWorld.goal);
  m.bumped = p.bumped;
  m.range = static_cast<std::uint8_t>(sensor.options().range);
  m.cells.resize(static_cast<std::size_t>(sensor.side() * sensor.side()));
  sensor.scan(kWorld.grid, p.position, deriveSeed(p.seed, {1}), p.steps, m.cells.data());
  if (p.steps == 0) {
    m.width = static_cast<std::uint32_t>(kWorld.grid.width());
    m.height = static_cast<std::uint32_t>(kWorld.grid.height());
    m.start = cell(kWorld.start);
    m.agent_seed = p.seed;
    if (prior_map) {
      for (int i = 0; i < kWorld.grid.size(); ++i) {
        m.prior_map.push_back(kWorld.grid.isObstacle(kWorld.grid.cellAt(i)) ? kScanObstacle : kScanFree);
      }
    }
  }
  return m;
}

/// Plays `count` episodes (seeds 100, 101, ...) through one responder, all in lockstep batches.
std::vector<test::Outcome> playBatched(const AgentConfig& c, int count, std::size_t* most_active) {
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
    ppp_msgs::ScanBatch batch;
    batch.agent = c.name;
    batch.batch = batch_number;
    std::vector<Played*> in_batch;
    for (Played& p : episodes) {
      if (p.done) continue;
      batch.scans.push_back(scanMessage(p, sensor, c.type == "astar"));
      in_batch.push_back(&p);
    }
    const ppp_msgs::MoveBatch moves = responder.answer(batch);
    // Episodes that ended in the previous round were finished by this batch.
    EXPECT_EQ(responder.active(), in_batch.size());
    *most_active = std::max(*most_active, responder.active());
    if (in_batch.empty()) break;
    EXPECT_EQ(moves.agent, c.name);
    EXPECT_EQ(moves.batch, batch_number);
    EXPECT_EQ(moves.moves.size(), in_batch.size());
    for (std::size_t i = 0; i < in_batch.size(); ++i) {
      Played& p = *in_batch[i];
      EXPECT_EQ(moves.moves[i].episode, p.id);
      EXPECT_EQ(moves.moves[i].step, static_cast<std::uint32_t>(p.steps));
      EXPECT_TRUE(isAction(moves.moves[i].action)) << int(moves.moves[i].action);
      const Action action = static_cast<Action>(moves.moves[i].action);
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
      std::size_t most_active = 0;
      const auto batched = playBatched(c, 6, &most_active);
      EXPECT_EQ(most_active, 6u);
      auto agent = makeAgent(c);
      for (int i = 0; i < 6; ++i) {
        const auto expected = test::runEpisode(*agent, kWorld, 100 + i, c.sensor_noise, 300, type == "astar");
        EXPECT_EQ(batched[i].passed, expected.passed) << type << " episode " << i;
        EXPECT_EQ(batched[i].steps, expected.steps) << type << " episode " << i;
        EXPECT_EQ(batched[i].bumps, expected.bumps) << type << " episode " << i;
        EXPECT_EQ(batched[i].path, expected.path) << type << " episode " << i;
      }
    }
  }
}

/// A well-formed step-0 scan of episode `id` on kWorld.
ppp_msgs::EpisodeScan startScan(std::uint32_t id, bool prior_map = false) {
  Played p{id, 5, kWorld.start};
  return scanMessage(p, SensorModel(SensorOptions{}), prior_map);
}

ppp_msgs::ScanBatch batchOf(const std::vector<ppp_msgs::EpisodeScan>& scans) {
  ppp_msgs::ScanBatch batch;
  batch.batch = 9;
  batch.scans = scans;
  return batch;
}

TEST(BatchResponderTest, MalformedScansAreRejectedOneByOne) {
  BatchResponder responder(config("astar"));
  ppp_msgs::EpisodeScan good = startScan(1, true);
  ppp_msgs::EpisodeScan short_cells = startScan(2, true);
  short_cells.cells.pop_back();
  ppp_msgs::EpisodeScan short_map = startScan(3, true);
  short_map.prior_map.pop_back();
  ppp_msgs::EpisodeScan bad_map_value = startScan(4, true);
  bad_map_value.prior_map[3] = 7;
  ppp_msgs::EpisodeScan no_map = startScan(5, false);  // astar needs its prior map
  ppp_msgs::EpisodeScan never_started = startScan(6, true);
  never_started.step = 3;
  ppp_msgs::EpisodeScan off_grid = startScan(7, true);
  off_grid.position.x = 99;
  ppp_msgs::EpisodeScan zero_size = startScan(8, true);
  zero_size.width = 0;
  ppp_msgs::EpisodeScan bad_range = startScan(9, true);
  bad_range.range = 0;
  const ppp_msgs::EpisodeScan duplicate = good;

  const auto moves = responder.answer(batchOf({good, short_cells, short_map, bad_map_value, no_map, never_started,
                                               off_grid, zero_size, bad_range, duplicate}));
  ASSERT_EQ(moves.moves.size(), 10u);
  EXPECT_EQ(moves.batch, 9u);
  EXPECT_TRUE(isAction(moves.moves[0].action));
  for (std::size_t i = 1; i < moves.moves.size(); ++i) {
    EXPECT_EQ(moves.moves[i].action, kRejectedAction) << i;
    EXPECT_EQ(moves.moves[i].episode, i == 9 ? 1u : static_cast<std::uint32_t>(i + 1)) << i;
  }
  EXPECT_EQ(responder.active(), 1u);  // only the good episode survives its duplicate
  const std::map<std::string, long> expected{{"cells", 1},    {"prior_map", 3}, {"episode", 1}, {"position", 1},
                                             {"size", 1},     {"range", 1},     {"duplicate", 1}};
  EXPECT_EQ(responder.rejections(), expected);

  // The good episode goes on; a rejected one stays rejected.
  ppp_msgs::EpisodeScan next = good;
  next.step = 1;
  short_cells.step = 1;
  const auto again = responder.answer(batchOf({next, short_cells}));
  EXPECT_TRUE(isAction(again.moves[0].action));
  EXPECT_EQ(again.moves[1].action, kRejectedAction);
}

TEST(BatchResponderTest, EpisodesMissingFromABatchAreFinishedAndIdsCanRestart) {
  BatchResponder responder(config("explorer"));
  responder.answer(batchOf({startScan(1), startScan(2), startScan(3)}));
  EXPECT_EQ(responder.active(), 3u);
  ppp_msgs::EpisodeScan two = startScan(2);
  two.step = 1;
  responder.answer(batchOf({two}));
  EXPECT_EQ(responder.active(), 1u);
  // Episode 1 is over: a later scan of it is rejected, a new step 0 starts it afresh.
  ppp_msgs::EpisodeScan one = startScan(1);
  one.step = 1;
  two.step = 2;
  EXPECT_EQ(responder.answer(batchOf({one, two})).moves[0].action, kRejectedAction);
  EXPECT_TRUE(isAction(responder.answer(batchOf({startScan(1)})).moves[0].action));
  EXPECT_EQ(responder.active(), 1u);
  EXPECT_TRUE(responder.answer(batchOf({})).moves.empty());
  EXPECT_EQ(responder.active(), 0u);
}

}  // namespace
}  // namespace agents
}  // namespace ppp
