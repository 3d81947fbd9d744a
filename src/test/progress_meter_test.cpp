#include "ppp_core/progress_meter.hpp"

#include <gtest/gtest.h>

namespace ppp {
namespace {

TEST(ProgressMeterTest, DurationsReadAsPeopleSayThem) {
  EXPECT_EQ(formatDuration(0), "0 s");
  EXPECT_EQ(formatDuration(44.6), "45 s");
  EXPECT_EQ(formatDuration(60), "1 min 00 s");
  EXPECT_EQ(formatDuration(182), "3 min 02 s");
  EXPECT_EQ(formatDuration(3600 + 5 * 60 + 10), "1 h 05 min");
  EXPECT_EQ(formatDuration(-3), "0 s");
}

TEST(ProgressMeterTest, ALineAtTheStartThenOneAnIntervalAndOneAtTheEnd) {
  ProgressMeter meter("episodes", "episodes", 5.0);
  EXPECT_EQ(meter.update(0, 1000, 100.0), "progress: episodes: 0/1000 episodes (0.0 %)");
  EXPECT_EQ(meter.update(50, 1000, 104.9), "");  // within the interval
  // 100 episodes in 10 s: 10 per second, 900 left: 90 s.
  EXPECT_EQ(meter.update(100, 1000, 110.0, "3 agents"),
            "progress: episodes: 100/1000 episodes (10.0 %), 10.0 episodes/s, ETA 1 min 30 s, 3 agents");
  EXPECT_EQ(meter.update(120, 1000, 112.0), "");
  // The end is always shown, once.
  EXPECT_EQ(meter.update(1000, 1000, 113.0), "progress: episodes: 1000/1000 episodes (100.0 %), 76.9 episodes/s, "
                                             "done in 13 s");
  EXPECT_EQ(meter.update(1000, 1000, 200.0), "");
}

TEST(ProgressMeterTest, TheRateCountsOnlyWhatWasDoneSinceTheFirstLine) {
  // A resumed run starts at 600 of 1000: 200 more in 20 s is 10 per second, 200 left: 20 s.
  ProgressMeter meter("set 'hunted'", "matings", 5.0);
  EXPECT_EQ(meter.update(600, 1000, 0.0), "progress: set 'hunted': 600/1000 matings (60.0 %)");
  EXPECT_EQ(meter.update(800, 1000, 20.0, "best fitness 0.5"),
            "progress: set 'hunted': 800/1000 matings (80.0 %), 10.0 matings/s, ETA 20 s, best fitness 0.5");
}

TEST(ProgressMeterTest, AnUnknownTotalGivesCountAndRateOnly) {
  ProgressMeter meter("hunt", "episodes", 2.0);
  EXPECT_EQ(meter.update(0, 0, 1.0), "progress: hunt: 0 episodes");
  EXPECT_EQ(meter.update(31250, 0, 3.5, "48 evaluations"), "progress: hunt: 31250 episodes, 12500 episodes/s, 48 evaluations");
}

TEST(ProgressMeterTest, LanesSideBySideShowTheTimeLeftOfTheSlowest) {
  // A grid agent's 1000 quick episodes and a planner's 10 slow ones, played side by side from t = 0. At t = 10 the
  // grid lane has done 990 (99 a second: 0.1 s left), the planner 1 (9 left at one per 10 s: 90 s). The ETA is the
  // planner's, and the share is of the time: 10 s of 100, though 981 of 1010 episodes (97 %) are done.
  ProgressMeter meter("episodes", "episodes", 5.0);
  EXPECT_EQ(meter.update({{"explorer", 0, 1000}, {"nd", 0, 10}}, 0.0),
            "progress: episodes: 0/1010 episodes (0.0 %), slowest: explorer 0/1000");
  EXPECT_EQ(meter.update({{"explorer", 990, 1000}, {"nd", 1, 10}}, 10.0),
            "progress: episodes: 991/1010 episodes (10.0 %), 99.1 episodes/s, ETA 1 min 30 s, slowest: nd 1/10");
  // The grid lane done, the planner's 9th at t = 90: one left at one per 10 s.
  EXPECT_EQ(meter.update({{"explorer", 1000, 1000}, {"nd", 9, 10}}, 90.0),
            "progress: episodes: 1009/1010 episodes (90.0 %), 11.2 episodes/s, ETA 10 s, slowest: nd 9/10");
  EXPECT_EQ(meter.update({{"explorer", 1000, 1000}, {"nd", 10, 10}}, 100.0),
            "progress: episodes: 1010/1010 episodes (100.0 %), 10.1 episodes/s, done in 1 min 40 s");
}

TEST(ProgressMeterTest, ALaneWithWorkLeftAndNothingDoneLeavesTheTimeUnknownAndNeverReadsAllDone) {
  // 9999 of 10000 episodes done by one lane; the other's one episode has not ended: the share is of the episodes
  // but held below 100 %, and the ETA is unknown.
  ProgressMeter meter("episodes", "episodes", 5.0);
  meter.update({{"explorer", 0, 9999}, {"tpspace", 0, 1}}, 0.0);
  EXPECT_EQ(meter.update({{"explorer", 9999, 9999}, {"tpspace", 0, 1}}, 20.0),
            "progress: episodes: 9999/10000 episodes (99.9 %), 500 episodes/s, ETA unknown, slowest: tpspace 0/1");
}

TEST(ProgressMeterTest, ALaneIsJudgedByItsRecentPaceNotByTheTimeItWaitedForTheOthers) {
  // A planner's lane gets no core while a grid lane plays its 1000 episodes (100 s), then ends one episode a second.
  // Its rate is reckoned over the last 30 s of updates: at t = 110 that reaches back to t = 0 (10 in 110 s: 170 left
  // take 1870 s); at t = 140, to t = 110 (30 in 30 s: 140 left take 140 s), where its rate since the start (40 in
  // 140 s) would say 490 s.
  ProgressMeter meter("episodes", "episodes", 5.0);
  meter.update({{"explorer", 0, 1000}, {"nd", 0, 180}}, 0.0);
  EXPECT_EQ(meter.update({{"explorer", 1000, 1000}, {"nd", 0, 180}}, 100.0),
            "progress: episodes: 1000/1180 episodes (84.7 %), 10.0 episodes/s, ETA unknown, slowest: nd 0/180");
  EXPECT_EQ(meter.update({{"explorer", 1000, 1000}, {"nd", 10, 180}}, 110.0),
            "progress: episodes: 1010/1180 episodes (5.6 %), 9.18 episodes/s, ETA 31 min 10 s, slowest: nd 10/180");
  EXPECT_EQ(meter.update({{"explorer", 1000, 1000}, {"nd", 40, 180}}, 140.0),
            "progress: episodes: 1040/1180 episodes (50.0 %), 7.43 episodes/s, ETA 2 min 20 s, slowest: nd 40/180");
}

}  // namespace
}  // namespace ppp
