// MRPT's wavefront planner called from two threads at once, as two planner nodelets of one manager call it.
// PlannerSimple2D::computePath (MRPT 2.x, through 2.15.19) keeps the step of its trace toward the target in
// function-static variables (`static signed char dx = 0, dy = 0;`, libs/nav/src/planners/PlannerSimple2D.cpp line
// 383 in 2.5.8; local since 3.0.0): a second thread's trace can overwrite the first's step between its choice and
// its use, and the first walks off its gradient. Its path is then wrong, or it never reaches the target and grows
// its path without bound, or MRPT's own check that the step is not (0, 0) fails when one thread's dx = 0 meets
// the other's dy = 0 (docs/explanation/findings.md).
//
// MRPT's race itself, without any code of ours, is mrpt_planner_race.cpp (docs/upstream/mrpt-planner-thread-race.md).
// This test checks PPP Lab's mitigation: MrptGridPlanner lets one plan at a time into MRPT, so two threads get the
// single-threaded paths, point for point.
// MRPT's holonomic reactive navigators (ND, VFF, FullEval) keep their memory (ND's and FullEval's last chosen
// sector) in each navigator object and no static data: one object per thread answers as it does alone.
#include <sys/resource.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "map_picture.hpp"
#include "mrpt_grid_planner.hpp"
#include "mrpt_reactive_navigator.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace planners {
namespace {

/// A winding 40x40 map: walls with alternating gaps, so each path is long and its trace-back takes many steps.
GridMap windingMap() {
  std::vector<std::string> picture(40, std::string(40, '.'));
  for (int wall = 4; wall < 40; wall += 5) {
    for (int x = 0; x < 40; ++x) picture[wall][x] = '#';
    picture[wall][(wall / 5) % 2 == 0 ? 37 : 2] = '.';
  }
  return test::mapPicture(picture);
}

/// True when two paths have the same points, exactly.
bool samePoints(const std::vector<MapPoint>& a, const std::vector<MapPoint>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const MapPoint& p, const MapPoint& q) { return p.x == q.x && p.y == q.y; });
}

TEST(MrptThreadsTest, TwoThreadsPlanningAtOnceGetTheAnswersOfOneThread) {
  // A runaway trace-back throws std::bad_alloc within this limit instead of taking the machine's memory.
  const rlimit limit{2ul << 30, 2ul << 30};
  ASSERT_EQ(setrlimit(RLIMIT_AS, &limit), 0);
  const GridMap map = windingMap();
  const MrptGridPlanner planner(0);
  const std::vector<std::pair<Cell, Cell>> requests = {{{1, 1}, {38, 38}}, {{38, 1}, {1, 38}}, {{20, 2}, {20, 37}}};
  std::vector<std::vector<MapPoint>> alone;
  for (const auto& [from, to] : requests) {
    alone.push_back(planner.plan(map, from, to));
    ASSERT_FALSE(alone.back().empty());
  }
  std::atomic<int> differing{0};
  std::atomic<int> failed{0};
  const auto plan_many = [&](std::size_t first) {
    for (int i = 0; i < 5000; ++i) {
      const std::size_t k = (first + i) % requests.size();
      try {
        if (!samePoints(planner.plan(map, requests[k].first, requests[k].second), alone[k])) ++differing;
      } catch (const Error&) {
        ++failed;
      }
    }
  };
  std::thread other(plan_many, 1);
  plan_many(0);
  other.join();
  EXPECT_EQ(differing, 0);
  EXPECT_EQ(failed, 0);
}

/// What a fresh navigator of `method` answers to each of `inputs` in turn (obstacles, target).
std::vector<Heading> headings(const std::string& method,
                              const std::vector<std::pair<std::vector<double>, MapPoint>>& inputs) {
  MrptReactiveNavigator navigator(method);
  std::vector<Heading> answers;
  for (const auto& [obstacles, target] : inputs) answers.push_back(navigator.navigate(obstacles, target));
  return answers;
}

TEST(MrptThreadsTest, ReactiveNavigatorsInThreadsOfTheirOwnAnswerAsAlone) {
  // 300 random scenes; ND and FullEval carry their last choice from call to call, so the order is kept.
  Rng rng(11);
  std::vector<std::pair<std::vector<double>, MapPoint>> inputs(300);
  for (auto& [obstacles, target] : inputs) {
    for (int k = 0; k < kReactiveSectors; ++k) obstacles.push_back(0.05 + 0.95 * rng.uniform01());
    target = MapPoint{2 * rng.uniform01() - 1, 2 * rng.uniform01() - 1};
  }
  for (const std::string& method : reactiveMethodNames()) {
    const std::vector<Heading> alone = headings(method, inputs);
    std::set<double> directions;
    for (const Heading& h : alone) directions.insert(h.direction);
    ASSERT_GT(directions.size(), 50u) << method << " answers the scenes alike: they test nothing";
    std::vector<std::vector<std::vector<Heading>>> together(3);  // three threads, each 20 passes over the scenes
    std::vector<std::thread> threads;
    for (auto& answers : together) {
      threads.emplace_back([&answers, &method, &inputs] {
        for (int pass = 0; pass < 20; ++pass) answers.push_back(headings(method, inputs));
      });
    }
    for (std::thread& t : threads) t.join();
    for (const auto& answers : together) {
      for (const std::vector<Heading>& pass : answers) {
        ASSERT_EQ(pass.size(), alone.size());
        for (std::size_t i = 0; i < alone.size(); ++i) {
          ASSERT_EQ(pass[i].direction, alone[i].direction) << method << " scene " << i;
          ASSERT_EQ(pass[i].speed, alone[i].speed) << method << " scene " << i;
        }
      }
    }
  }
}

}  // namespace
}  // namespace planners
}  // namespace ppp
