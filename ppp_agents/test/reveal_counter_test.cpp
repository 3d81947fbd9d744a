#include "ppp_agents/reveal_counter.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "ppp_core/action.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/visibility.hpp"

namespace ppp {
namespace agents {
namespace {

/// Memory of a width x height map after one scan of range `range` at `position` whose window cells are `cells`.
AgentMemory rememberScan(int width, int height, Cell position, int range, const std::vector<std::int8_t>& cells) {
  AgentMemory memory;
  memory.reset(width, height, 0);
  memory.update(Scan(range, cells, position, Cell{0, 0}, false, 0));
  return memory;
}

/// revealGains() as a value.
std::array<int, 4> gainsOf(const AgentMemory& memory, Cell position, int range, const std::array<bool, 4>& evaluate) {
  std::array<int, 4> gains;
  revealGains(memory, position, range, evaluate, &gains);
  return gains;
}

/// The gains counted cell by cell: every window cell of the neighbour, with its line of sight walked.
std::array<int, 4> bruteForceGains(const AgentMemory& memory, Cell position, int range,
                                   const std::array<bool, 4>& evaluate) {
  std::array<int, 4> gains{};
  for (int n = 0; n < 4; ++n) {
    if (!evaluate[n]) continue;
    const Cell from = target(position, kMoves[n]);
    for (int dy = -range; dy <= range; ++dy) {
      for (int dx = -range; dx <= range; ++dx) {
        if (!memory.isUnknown(Cell{from.x + dx, from.y + dy})) continue;
        bool hidden = false;
        for (Cell b : cellsCrossed(Cell{0, 0}, Cell{dx, dy})) {
          hidden = hidden || memory.at(Cell{from.x + b.x, from.y + b.y}) == kScanObstacle;
        }
        gains[n] += hidden ? 0 : 1;
      }
    }
  }
  return gains;
}

TEST(RevealCounterTest, CountsUnknownCellsNotBehindRememberedObstacles) {
  // 9x9 map; a range-1 scan at (4, 4) showed the 3x3 block x, y in 3..5 free but (4, 3), north of the agent.
  const AgentMemory memory = rememberScan(9, 9, Cell{4, 4}, 1,
                                          {kScanFree, kScanObstacle, kScanFree,  //
                                           kScanFree, kScanFree, kScanFree,      //
                                           kScanFree, kScanFree, kScanFree});
  // Range 2 from each neighbour: 25 window cells, 9 of them known, 16 unknown.
  // North (4, 3) is the obstacle: not evaluated.
  // East (5, 4): the obstacle at offset (-1, -1) hides (-2, -2) (the diagonal through its centre) and
  // (-1, -2), (-2, -1) (whose segments pass through its interior): (3, 2) and (4, 2) are unknown, (3, 3) is
  // known, so 16 - 2 = 14. West (3, 4) mirrors East: 14.
  // South (4, 5): the obstacle is at offset (0, -2), the window's edge, and hides nothing in it: 16.
  const std::array<bool, 4> evaluate{false, true, true, true};
  const std::array<int, 4> expected{0, 14, 16, 14};
  EXPECT_EQ(bruteForceGains(memory, Cell{4, 4}, 2, evaluate), expected);
  EXPECT_EQ(gainsOf(memory, Cell{4, 4}, 2, evaluate), expected);
}

TEST(RevealCounterTest, OffMapCellsAreNeitherUnknownNorHiding) {
  // 3x3 map, all unknown, agent in the corner (0, 0): East (1, 0) with range 1 sees x 0..2, y 0..1 on the map
  // (6 cells, the agent's own cell unknown too since nothing was scanned); South likewise; North and West
  // are off the map.
  AgentMemory memory;
  memory.reset(3, 3, 0);
  const std::array<int, 4> expected{0, 6, 6, 0};
  EXPECT_EQ(gainsOf(memory, Cell{0, 0}, 1, {false, true, true, false}), expected);
}

TEST(RevealCounterTest, AgreesWithTheLineOfSightWalkOnRandomMemoriesAtEveryRange) {
  Rng rng(11);
  for (int range = 1; range <= kMaxSensorRange; ++range) {
    for (int trial = 0; trial < 400; ++trial) {
      // A memory of a map a little larger than the board, filled by one scan of the largest range with
      // random free / obstacle / unknown cells, seen from a random position (near the edges too).
      // Every other trial on a map 60 cells wider, seen and counted around column 64, where the memory's
      // rows change words.
      const bool wide = trial % 2 == 1;
      const int width = 2 * range + 1 + static_cast<int>(rng.below(12)) + (wide ? 60 : 0);
      const int height = 2 * range + 1 + static_cast<int>(rng.below(12));
      const int obstacle_percent = 5 + static_cast<int>(rng.below(40));
      std::vector<std::int8_t> cells;
      for (int i = 0; i < kMaxScanCells; ++i) {
        const int draw = static_cast<int>(rng.below(100));
        cells.push_back(draw < obstacle_percent ? kScanObstacle : draw < 70 ? kScanFree : kScanUnknown);
      }
      const Cell centre{wide ? 57 + static_cast<int>(rng.below(14))
                             : static_cast<int>(rng.below(static_cast<std::uint64_t>(width))),
                        static_cast<int>(rng.below(static_cast<std::uint64_t>(height)))};
      const AgentMemory memory = rememberScan(width, height, centre, kMaxSensorRange, cells);
      const Cell position{wide ? centre.x - 4 + static_cast<int>(rng.below(9))
                               : static_cast<int>(rng.below(static_cast<std::uint64_t>(width))),
                          static_cast<int>(rng.below(static_cast<std::uint64_t>(height)))};
      std::array<bool, 4> evaluate{};
      for (bool& e : evaluate) e = rng.below(4) != 0;
      ASSERT_EQ(gainsOf(memory, position, range, evaluate), bruteForceGains(memory, position, range, evaluate))
          << "range " << range << ", trial " << trial;
    }
  }
}

}  // namespace
}  // namespace agents
}  // namespace ppp
