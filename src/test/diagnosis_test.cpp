#include "ppp_core/diagnosis.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ppp_core/episode_reason.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace {

/// Cells along row 0 at the x positions given.
std::vector<Cell> row(const std::vector<int>& xs) {
  std::vector<Cell> cells;
  for (const int x : xs) cells.push_back(Cell{x, 0});
  return cells;
}

/// x = 0, 1, ..., last.
std::vector<int> walkEast(int last) {
  std::vector<int> xs;
  for (int x = 0; x <= last; ++x) xs.push_back(x);
  return xs;
}

TEST(DiagnosisTest, TheFinalWindowIsTheLastQuarterRoundedUpAndAtLeastFourActions) {
  EXPECT_EQ(finalWindow(300), 75);
  EXPECT_EQ(finalWindow(301), 76);
  EXPECT_EQ(finalWindow(40), 10);
  EXPECT_EQ(finalWindow(10), 4);  // a quarter would be 3
  EXPECT_EQ(finalWindow(3), 3);
  EXPECT_EQ(finalWindow(1), 1);
}

TEST(DiagnosisTest, ARobotThatStaysPutOverTheFinalWindowIsStuckSinceItsLastMove) {
  // 12 moves east, then 8 bumps or stays: 20 actions, window 5; the cell is unchanged since step 12.
  std::vector<int> xs = walkEast(12);
  xs.insert(xs.end(), 8, 12);
  const Diagnosis d = diagnoseTrajectory(row(xs));
  EXPECT_STREQ(d.kind, diagnosis::kStuck);
  EXPECT_EQ(d.step, 12);
  EXPECT_EQ(d.period, 0);
  EXPECT_EQ(d.endless_step, -1);
}

TEST(DiagnosisTest, ShuttlingBetweenTwoCellsIsALoopOfPeriodTwoFromTheFirstRepeatedCell) {
  // East to x = 10 (step 10), then 11, 10, 11, 10, ... up to 40 actions. Cells at steps t and t + 2 agree from
  // t = 10 on (10, 11, 10, ...) but not at t = 9 (9 against 11).
  std::vector<int> xs = walkEast(10);
  while (xs.size() < 41) xs.push_back(xs.size() % 2 == 1 ? 11 : 10);
  const Diagnosis d = diagnoseTrajectory(row(xs));
  EXPECT_STREQ(d.kind, diagnosis::kLoop);
  EXPECT_EQ(d.period, 2);
  EXPECT_EQ(d.step, 10);
  EXPECT_EQ(d.endless_step, -1);  // no states given
}

TEST(DiagnosisTest, CirclingAnIslandIsALoopOfItsPerimeterEnteredMidCycle) {
  // The ring of 8 cells around the island (1, 1), entered from below at (0, 2) after two moves north.
  const std::vector<Cell> ring = {{0, 2}, {0, 1}, {0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}};
  std::vector<Cell> cells = {{0, 4}, {0, 3}};
  while (cells.size() < 41) cells.push_back(ring[(cells.size() - 2) % ring.size()]);
  const Diagnosis d = diagnoseTrajectory(cells);
  EXPECT_STREQ(d.kind, diagnosis::kLoop);
  EXPECT_EQ(d.period, 8);
  EXPECT_EQ(d.step, 2);  // (0, 3) at step 1 is not (0, 1) at step 9
}

TEST(DiagnosisTest, ABumpInTheCycleCountsInItsPeriod) {
  // The same ring with a bump at (2, 0): 9 actions per cycle over 8 cells.
  const std::vector<Cell> ring = {{0, 2}, {0, 1}, {0, 0}, {1, 0}, {2, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}};
  std::vector<Cell> cells = {{0, 3}};
  while (cells.size() < 61) cells.push_back(ring[(cells.size() - 1) % ring.size()]);
  const Diagnosis d = diagnoseTrajectory(cells);
  EXPECT_STREQ(d.kind, diagnosis::kLoop);
  EXPECT_EQ(d.period, 9);
  EXPECT_EQ(d.step, 1);
}

TEST(DiagnosisTest, TheSmallestPeriodIsReported) {
  // 0, 1, 0, 1, ... is periodic with 2, 4, 6, ...
  std::vector<int> xs;
  for (int t = 0; t <= 40; ++t) xs.push_back(t % 2);
  const Diagnosis d = diagnoseTrajectory(row(xs));
  EXPECT_STREQ(d.kind, diagnosis::kLoop);
  EXPECT_EQ(d.period, 2);
  EXPECT_EQ(d.step, 0);
}

TEST(DiagnosisTest, ACycleSeenLessThanTwiceOrShorterThanTheWindowIsNoLoop) {
  // East to x = 30, then round the 8-cell ring once and a bit (10 actions): 40 actions, window 10; the ring's
  // tail of 10 actions covers the window but not two cycles. Cells of the ring are new up to step 37.
  const std::vector<Cell> ring = {{30, 0}, {31, 0}, {32, 0}, {32, 1}, {32, 2}, {31, 2}, {30, 2}, {30, 1}};
  std::vector<Cell> cells = row(walkEast(29));
  while (cells.size() < 41) cells.push_back(ring[(cells.size() - 30) % ring.size()]);
  const Diagnosis d = diagnoseTrajectory(cells);
  EXPECT_STREQ(d.kind, diagnosis::kWandering);
  EXPECT_EQ(d.step, 37);
}

TEST(DiagnosisTest, AnAperiodicWalkOverCellsStoodOnBeforeIsConfinedSinceItsLastNewCell) {
  // East to x = 9 (new cells up to step 9), then swings of growing amplitude inside 3..9: never periodic.
  std::vector<int> xs = walkEast(9);
  for (int low = 8; low >= 3; --low) {
    for (int x = 8; x >= low; --x) xs.push_back(x);
    for (int x = low + 1; x <= 9; ++x) xs.push_back(x);
  }
  const Diagnosis d = diagnoseTrajectory(row(xs));
  EXPECT_STREQ(d.kind, diagnosis::kConfined);
  EXPECT_EQ(d.step, 10);
}

TEST(DiagnosisTest, ARobotStillReachingNewCellsIsWanderingUpToItsLastNewCell) {
  EXPECT_STREQ(diagnoseTrajectory(row(walkEast(40))).kind, diagnosis::kWandering);
  EXPECT_EQ(diagnoseTrajectory(row(walkEast(40))).step, 40);
  // Back and forth over old cells until the last action, which reaches x = 6 for the first time.
  std::vector<int> xs = walkEast(5);
  for (int i = 0; i < 7; ++i) {
    for (int x = 4; x >= 0; --x) xs.push_back(x);
    for (int x = 1; x <= 5; ++x) xs.push_back(x);
  }
  xs.push_back(6);
  const Diagnosis d = diagnoseTrajectory(row(xs));
  EXPECT_STREQ(d.kind, diagnosis::kWandering);
  EXPECT_EQ(d.step, static_cast<int>(xs.size()) - 1);
}

TEST(DiagnosisTest, VeryShortRuns) {
  EXPECT_STREQ(diagnoseTrajectory(row({0})).kind, diagnosis::kStuck);  // no action at all
  EXPECT_STREQ(diagnoseTrajectory(row({0, 0})).kind, diagnosis::kStuck);
  EXPECT_STREQ(diagnoseTrajectory(row({0, 1})).kind, diagnosis::kWandering);
  EXPECT_STREQ(diagnoseTrajectory(row({0, 1, 0})).kind, diagnosis::kWandering);  // window 2: x = 1 is new
  EXPECT_STREQ(diagnoseTrajectory(row({0, 1, 0, 1, 0})).kind, diagnosis::kLoop);  // 4 actions: two cycles
}

TEST(DiagnosisTest, ALoopIsEndlessFromTheFirstStepWhoseWholeStateRecursOnePeriodLater) {
  std::vector<int> xs = walkEast(10);
  while (xs.size() < 41) xs.push_back(xs.size() % 2 == 1 ? 11 : 10);
  // One digest per action: all different up to action 14 (the agent still learned), then two alternating ones.
  std::vector<std::uint64_t> states;
  for (int t = 0; t < 40; ++t) states.push_back(t < 15 ? 1000 + t : 7 + t % 2);
  Diagnosis d = diagnoseTrajectory(row(xs), states);
  EXPECT_STREQ(d.kind, diagnosis::kLoop);
  EXPECT_EQ(d.endless_step, 15);
  // A digest of 0 is "no state given": never a proof.
  for (std::uint64_t& s : states) s = 0;
  EXPECT_EQ(diagnoseTrajectory(row(xs), states).endless_step, -1);
  // States that never recur one period apart prove nothing.
  for (int t = 0; t < 40; ++t) states[t] = 1000 + t;
  EXPECT_EQ(diagnoseTrajectory(row(xs), states).endless_step, -1);
}

TEST(DiagnosisTest, RandomWalksAreNeverLoopsOrStuck) {
  // A uniform walk over the five actions on an open 20 x 20 grid for 300 actions. Being periodic over the last
  // 75 actions has a probability far below 1e-30 per run, so over 2,000 runs a loop or stuck would be the
  // rule's fault.
  Rng rng(2026);
  for (int run = 0; run < 2000; ++run) {
    std::vector<Cell> cells = {{0, 0}};
    for (int t = 0; t < 300; ++t) {
      Cell c = cells.back();
      switch (rng.below(5)) {
        case 1: c.y = std::max(c.y - 1, 0); break;
        case 2: c.x = std::min(c.x + 1, 19); break;
        case 3: c.y = std::min(c.y + 1, 19); break;
        case 4: c.x = std::max(c.x - 1, 0); break;
        default: break;
      }
      cells.push_back(c);
    }
    const std::string kind = diagnoseTrajectory(cells).kind;
    ASSERT_TRUE(kind == diagnosis::kConfined || kind == diagnosis::kWandering) << "run " << run << ": " << kind;
  }
}

TEST(DiagnosisTest, ARunIsDiagnosedByHowItEnded) {
  const std::vector<Cell> cells = row({0, 1, 0, 1, 0, 1, 0, 1, 0});
  EXPECT_STREQ(diagnoseRun(true, false, reason::kGoalReached, cells).kind, "");
  EXPECT_STREQ(diagnoseRun(true, true, reason::kGoalReached, cells).kind, diagnosis::kDetour);
  EXPECT_STREQ(diagnoseRun(false, false, reason::kBudgetExhausted, cells).kind, diagnosis::kLoop);
  EXPECT_STREQ(diagnoseRun(false, false, reason::kActionLimit, cells).kind, diagnosis::kLoop);
  EXPECT_STREQ(diagnoseRun(false, false, reason::kNoPath, cells, {}, diagnosis::kMissedRoute).kind,
               diagnosis::kMissedRoute);
  EXPECT_STREQ(diagnoseRun(false, false, reason::kNoPath, cells).kind, diagnosis::kReported);
  EXPECT_STREQ(diagnoseRun(false, false, reason::kCollision, cells).kind, diagnosis::kReported);
  EXPECT_EQ(diagnoseRun(false, false, reason::kCollision, cells).step, -1);
}

TEST(DiagnosisTest, KindsAreKnownByName) {
  for (const char* kind : {diagnosis::kStuck, diagnosis::kLoop, diagnosis::kConfined, diagnosis::kWandering,
                           diagnosis::kDetour, diagnosis::kMissedRoute, diagnosis::kNoRoute, diagnosis::kReported}) {
    EXPECT_STREQ(diagnosis::kindNamed(kind), kind);
  }
  EXPECT_EQ(diagnosis::kindIndex(diagnosis::kLoop), 1);
  EXPECT_EQ(diagnosis::kindIndex("budget_exhausted"), -1);
  EXPECT_EQ(diagnosis::kindNamed("budget_exhausted"), nullptr);
  EXPECT_EQ(diagnosis::kindNamed(""), nullptr);
}

TEST(DiagnosisTest, ALoopsCycleCellsAreItsDistinctCellsInOrder) {
  const std::vector<Cell> ring = {{0, 2}, {0, 1}, {0, 0}, {1, 0}, {2, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}};
  std::vector<Cell> cells = {{0, 3}};
  while (cells.size() < 61) cells.push_back(ring[(cells.size() - 1) % ring.size()]);
  const Diagnosis d = diagnoseTrajectory(cells);
  const std::vector<Cell> cycle = cycleCells(d, cells);
  ASSERT_EQ(cycle.size(), 8u);  // 9 actions, one of them a bump
  EXPECT_EQ(cycle.front(), (Cell{0, 2}));
  EXPECT_EQ(cycle.back(), (Cell{1, 2}));
  EXPECT_TRUE(cycleCells(diagnoseTrajectory(row(walkEast(40))), row(walkEast(40))).empty());
}

TEST(DiagnosisTest, DescriptionsNameTheStepsAndThePeriod) {
  Diagnosis loop;
  loop.kind = diagnosis::kLoop;
  loop.step = 56;
  loop.period = 2;
  EXPECT_EQ(describeDiagnosis(loop, reason::kBudgetExhausted, 2),
            "loop: from step 56 the robot repeats a cycle of 2 actions over 2 cells to the end, sensing nothing new");
  loop.endless_step = 58;
  const std::string endless = describeDiagnosis(loop, reason::kBudgetExhausted, 2);
  EXPECT_NE(endless.find("the whole state at step 58"), std::string::npos) << endless;
  EXPECT_NE(endless.find("recurred at step 60"), std::string::npos) << endless;
  Diagnosis reported;
  reported.kind = diagnosis::kReported;
  EXPECT_EQ(describeDiagnosis(reported, reason::kCollision), "reported: the run ended as collision");
  EXPECT_EQ(describeDiagnosis(Diagnosis{}, reason::kGoalReached), "");
}

}  // namespace
}  // namespace ppp

namespace ppp {
namespace {

/// The cells of a continuous run that enters the cells `entered` in order, staying `dwell[i % dwell.size()]`
/// control periods on the i-th, on row 0.
std::vector<Cell> dwelling(const std::vector<int>& entered, const std::vector<int>& dwell) {
  std::vector<Cell> cells;
  for (std::size_t i = 0; i < entered.size(); ++i) {
    for (int k = 0; k < dwell[i % dwell.size()]; ++k) cells.push_back(Cell{entered[i], 0});
  }
  return cells;
}

TEST(ContinuousDiagnosisTest, CirclingIsALoopOfTheCellsEnteredWhateverTheTimeSpentInEach) {
  // Out along 0 1 2, then round 3 4 5 6 five times, staying 3, 5, 4, 2, 6, 3, 7 periods in turn: no period in
  // time, but the cells entered repeat 3 4 5 6 from the 4th entry (period 4). The 3 entries before it took
  // 3 + 5 + 4 = 12 periods, so the loop begins at period 12.
  std::vector<int> entered = {0, 1, 2};
  for (int lap = 0; lap < 5; ++lap) entered.insert(entered.end(), {3, 4, 5, 6});
  const std::vector<Cell> cells = dwelling(entered, {3, 5, 4, 2, 6, 3, 7});
  EXPECT_STRNE(diagnoseTrajectory(cells).kind, diagnosis::kLoop);  // the grid's rule sees no period in time
  const Diagnosis d = diagnoseContinuousTrajectory(cells);
  EXPECT_STREQ(d.kind, diagnosis::kLoop);
  EXPECT_EQ(d.period, 4);
  EXPECT_EQ(d.step, 12);
  EXPECT_EQ(d.endless_step, -1);
}

TEST(ContinuousDiagnosisTest, StuckConfinedAndWanderingAreJudgedOverControlPeriods) {
  // 0 1 2 then 40 periods on 2: stuck since period 2 (each cell one period).
  std::vector<Cell> still = dwelling({0, 1, 2}, {1});
  still.insert(still.end(), 40, Cell{2, 0});
  const Diagnosis stuck = diagnoseContinuousTrajectory(still);
  EXPECT_STREQ(stuck.kind, diagnosis::kStuck);
  EXPECT_EQ(stuck.step, 2);
  // New cells to the end: wandering, up to the last new cell (entered at period 2 x 9 = 18).
  const Diagnosis wandering = diagnoseContinuousTrajectory(dwelling({0, 1, 2, 3, 4, 5, 6, 7, 8, 9}, {2}));
  EXPECT_STREQ(wandering.kind, diagnosis::kWandering);
  EXPECT_EQ(wandering.step, 18);
  // Back over cells stood on before with no period among the cells entered: confined since the last new cell
  // (cell 3 entered at period 3, so from period 4).
  const Diagnosis confined =
      diagnoseContinuousTrajectory(dwelling({0, 1, 2, 3, 2, 1, 2, 3, 2, 1, 0, 1, 0, 1, 2, 1, 2, 3, 2}, {1}));
  EXPECT_STREQ(confined.kind, diagnosis::kConfined);
  EXPECT_EQ(confined.step, 4);
}

TEST(ContinuousDiagnosisTest, AContinuousRunIsDiagnosedByHowItEnded) {
  std::vector<int> entered;
  for (int lap = 0; lap < 5; ++lap) entered.insert(entered.end(), {3, 4});
  const std::vector<Cell> cells = dwelling(entered, {2, 3});
  EXPECT_STREQ(diagnoseContinuousRun(false, false, reason::kBudgetExhausted, cells).kind, diagnosis::kLoop);
  EXPECT_STREQ(diagnoseContinuousRun(false, false, reason::kCollision, cells).kind, diagnosis::kReported);
  EXPECT_STREQ(diagnoseContinuousRun(true, false, reason::kGoalReached, cells).kind, "");
}

}  // namespace
}  // namespace ppp
