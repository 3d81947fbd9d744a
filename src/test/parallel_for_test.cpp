#include "ppp_core/parallel_for.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace ppp {
namespace {

TEST(ParallelForTest, CallsEveryIndexOnceForAnyThreadCount) {
  for (const int threads : {0, 1, 2, 3, 16}) {
    std::vector<std::atomic<int>> calls(101);
    parallelFor(calls.size(), threads, [&](std::size_t i) { ++calls[i]; });
    for (std::size_t i = 0; i < calls.size(); ++i) EXPECT_EQ(calls[i].load(), 1) << "index " << i << ", threads " << threads;
  }
}

TEST(ParallelForTest, NothingToDoCallsNothing) {
  bool called = false;
  parallelFor(0, 4, [&](std::size_t) { called = true; });
  EXPECT_FALSE(called);
}

TEST(ParallelForTest, ResultsWrittenByIndexDoNotDependOnTheThreads) {
  const auto squares = [](int threads) {
    std::vector<long> out(50);
    parallelFor(out.size(), threads, [&](std::size_t i) { out[i] = static_cast<long>(i * i); });
    return out;
  };
  const std::vector<long> one = squares(1);
  EXPECT_EQ(one[7], 49);
  EXPECT_EQ(squares(4), one);
}

TEST(ParallelForTest, TwoThreadsRunTwoTasksAtOnce) {
  // Each task waits (up to 10 s) for the other to have started: one after the other, the first would give up.
  std::atomic<int> started{0};
  std::vector<int> seen(2);
  parallelFor(2, 2, [&](std::size_t i) {
    ++started;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (started.load() < 2 && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
    seen[i] = started.load();
  });
  EXPECT_EQ(seen, (std::vector<int>{2, 2}));
}

TEST(ParallelForTest, RethrowsTheLowestFailingIndexAfterEveryTaskEnded) {
  std::atomic<int> ended{0};
  try {
    parallelFor(20, 3, [&](std::size_t i) {
      ++ended;
      if (i == 13 || i == 5) throw std::runtime_error("task " + std::to_string(i));
    });
    FAIL() << "nothing thrown";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "task 5");
  }
  EXPECT_EQ(ended.load(), 20);
}

}  // namespace
}  // namespace ppp
