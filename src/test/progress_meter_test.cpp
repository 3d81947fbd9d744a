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

}  // namespace
}  // namespace ppp
