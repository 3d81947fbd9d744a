// PlannerSimple2D::computePath from two threads at once, each with a planner and a map of its own: the paths that
// differ from the single-threaded ones, the traces that never end (caught as std::bad_alloc under a 2 GB address
// space) and MRPT's own failed check of the trace's step. Usage: mrpt_planner_race [PLANS_PER_THREAD]
// [--expect-race]. Exits 1 when one thread alone does not answer the same every time, or, with --expect-race, when
// nothing was caught; else 0, whatever the counts (how often two threads meet in the trace is the scheduler's).
// Built with a sanitizer (-fsanitize=thread or address), it leaves the address space unlimited: the sanitizers
// reserve terabytes of it for their shadow memory.
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/nav/planners/PlannerSimple2D.h>
#include <mrpt/poses/CPose2D.h>
#include <sys/resource.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <exception>
#include <new>
#include <string>
#include <thread>
#include <vector>

#if defined(__SANITIZE_THREAD__) || defined(__SANITIZE_ADDRESS__)
#define SANITIZED_BUILD 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer) || __has_feature(address_sanitizer)
#define SANITIZED_BUILD 1
#endif
#endif

using Path = std::deque<mrpt::math::TPoint2D>;

// A 40 x 40 map of 1 m cells: a wall every 5 rows with a one-cell gap at alternate ends, so every path winds
// through all of them and its trace takes hundreds of steps.
mrpt::maps::COccupancyGridMap2D windingMap() {
  mrpt::maps::COccupancyGridMap2D map;
  map.setSize(0, 40, 0, 40, 1.0f, 1.0f);
  for (int wall = 4; wall < 40; wall += 5) {
    for (int x = 0; x < 40; ++x) {
      if (x != ((wall / 5) % 2 == 0 ? 37 : 2)) map.setCell(x, wall, 0.0f);
    }
  }
  return map;
}

const double kRequests[3][4] = {{1.5, 1.5, 38.5, 38.5}, {38.5, 1.5, 1.5, 38.5}, {20.5, 2.5, 20.5, 37.5}};

Path plan(const mrpt::nav::PlannerSimple2D& planner, const mrpt::maps::COccupancyGridMap2D& map, int k) {
  Path path;
  bool not_found = true;
  const double* r = kRequests[k];
  planner.computePath(map, mrpt::poses::CPose2D(r[0], r[1], 0), mrpt::poses::CPose2D(r[2], r[3], 0), path, not_found);
  return path;
}

bool same(const Path& a, const Path& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].x != b[i].x || a[i].y != b[i].y) return false;
  }
  return true;
}

int main(int argc, char** argv) {
  const long plans = argc > 1 ? std::atol(argv[1]) : 3000;
  const bool expect_race = argc > 2 && std::string(argv[2]) == "--expect-race";
#ifndef SANITIZED_BUILD
  const rlimit limit{2ul << 30, 2ul << 30};
  setrlimit(RLIMIT_AS, &limit);
#endif
  mrpt::nav::PlannerSimple2D planner;
  planner.robotRadius = 0;            // the gaps are one cell wide
  planner.minStepInReturnedPath = 0;  // every cell of a path is a point
  const mrpt::maps::COccupancyGridMap2D map = windingMap();
  std::vector<Path> alone;
  for (int k = 0; k < 3; ++k) {
    alone.push_back(plan(planner, map, k));
    if (alone.back().size() < 40) {
      std::printf("request %d: %zu path points, not a long winding path\n", k, alone.back().size());
      return 1;
    }
  }
  for (int i = 0; i < 30; ++i) {
    if (!same(plan(planner, map, i % 3), alone[i % 3])) {
      std::printf("one thread alone answered request %d differently\n", i % 3);
      return 1;
    }
  }
  std::atomic<long> wrong{0}, runaway{0}, asserted{0};
  const auto plan_many = [&](int first) {
    const mrpt::nav::PlannerSimple2D own_planner = planner;
    const mrpt::maps::COccupancyGridMap2D own_map = windingMap();
    for (long i = 0; i < plans; ++i) {
      const int k = static_cast<int>((first + i) % 3);
      try {
        if (!same(plan(own_planner, own_map, k), alone[k])) ++wrong;
      } catch (const std::bad_alloc&) {
        ++runaway;
      } catch (const std::exception&) {  // MRPT's ASSERT_(dx != 0 || dy != 0)
        ++asserted;
      }
    }
  };
  std::thread other(plan_many, 1);
  plan_many(0);
  other.join();
  std::printf("%ld plans in two threads: %ld wrong paths, %ld runaway traces, %ld failed assertions\n", 2 * plans,
              wrong.load(), runaway.load(), asserted.load());
  return expect_race && wrong + runaway + asserted == 0 ? 1 : 0;
}
