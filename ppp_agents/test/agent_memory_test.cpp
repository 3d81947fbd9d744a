#include "ppp_agents/agent_memory.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ppp_core/rng.hpp"

namespace ppp {
namespace agents {
namespace {

/// A received scan drawn as rows: '.' free, '#' obstacle, '?' unknown, 'x' out of bounds; (2r+1) rows.
Scan drawnScan(Cell position, const std::vector<std::string>& rows) {
  std::vector<std::int8_t> cells;
  for (const std::string& row : rows) {
    for (char c : row) {
      cells.push_back(c == '.' ? kScanFree : c == '#' ? kScanObstacle : c == 'x' ? kScanOutOfBounds : kScanUnknown);
    }
  }
  return Scan(static_cast<int>(rows.size()) / 2, cells, position, Cell{0, 0}, false, 0);
}

/// Memory drawn as rows: '.' free, '#' obstacle, '?' unknown.
std::vector<std::string> draw(const AgentMemory& memory) {
  std::vector<std::string> rows;
  for (int y = 0; y < memory.height(); ++y) {
    std::string row;
    for (int x = 0; x < memory.width(); ++x) {
      const std::int8_t v = memory.at(Cell{x, y});
      row += v == kScanFree ? '.' : v == kScanObstacle ? '#' : '?';
    }
    rows.push_back(row);
  }
  return rows;
}

/// A range-2 scan at `position` of an open map with an obstacle at `obstacle` (if in the window), every
/// off-map cell out of bounds.
Scan openScan(Cell position, int width, int height, Cell obstacle) {
  std::vector<std::string> rows;
  for (int dy = -2; dy <= 2; ++dy) {
    std::string row;
    for (int dx = -2; dx <= 2; ++dx) {
      const Cell c{position.x + dx, position.y + dy};
      const bool on_map = c.x >= 0 && c.y >= 0 && c.x < width && c.y < height;
      row += !on_map ? 'x' : c == obstacle ? '#' : '.';
    }
    rows.push_back(row);
  }
  return drawnScan(position, rows);
}

TEST(AgentMemoryTest, StartsUnknownAndReportsOffMapCellsAsOutOfBounds) {
  AgentMemory memory;
  memory.reset(4, 3, 0);
  EXPECT_EQ(draw(memory), (std::vector<std::string>{"????", "????", "????"}));
  EXPECT_TRUE(memory.isUnknown(Cell{3, 2}));
  EXPECT_EQ(memory.at(Cell{-1, 0}), kScanOutOfBounds);
  EXPECT_EQ(memory.at(Cell{4, 0}), kScanOutOfBounds);
  EXPECT_FALSE(memory.isUnknown(Cell{0, 3}));
  EXPECT_FALSE(memory.isFree(Cell{0, -1}));
}

TEST(AgentMemoryTest, FullMemoryAccumulatesKnownCells) {
  AgentMemory memory;
  memory.reset(6, 4, 0);
  memory.update(drawnScan(Cell{1, 1}, {
                                          ".#.",
                                          "..?",
                                          "#..",
                                      }));
  EXPECT_EQ(draw(memory), (std::vector<std::string>{
                              ".#.???",
                              "..????",
                              "#..???",
                              "??????",
                          }));
  memory.update(drawnScan(Cell{4, 2}, {
                                          "..#",
                                          ".?.",
                                          "#..",
                                      }));
  EXPECT_EQ(draw(memory), (std::vector<std::string>{
                              ".#.???",
                              "..?..#",
                              "#...?.",
                              "???#..",
                          }));
}

TEST(AgentMemoryTest, UnknownAndOutOfBoundsScanCellsNeverOverwriteMemory) {
  AgentMemory memory;
  memory.reset(3, 3, 0);
  memory.update(drawnScan(Cell{1, 1}, {
                                          "#..",
                                          ".#.",
                                          "..#",
                                      }));
  // Seen again from the corner: the far cells are hidden now (unknown) and the window hangs off the map.
  memory.update(drawnScan(Cell{0, 0}, {
                                          "xxx",
                                          "x.?",
                                          "x??",
                                      }));
  EXPECT_EQ(draw(memory), (std::vector<std::string>{
                              "...",
                              ".#.",
                              "..#",
                          }));
  // A later reading replaces an earlier one (the cell at (2,2) was misreported, say).
  memory.update(drawnScan(Cell{1, 1}, {
                                          "???",
                                          "???",
                                          "??.",
                                      }));
  EXPECT_EQ(memory.at(Cell{2, 2}), kScanFree);
}

TEST(AgentMemoryTest, FiveByFiveWindowForgetsCellsThatLeftIt) {
  AgentMemory memory;
  memory.reset(9, 7, 5);
  const Cell obstacle{1, 3};
  memory.update(openScan(Cell{2, 2}, 9, 7, obstacle));
  EXPECT_EQ(draw(memory), (std::vector<std::string>{
                              ".....????",
                              ".....????",
                              ".....????",
                              ".#...????",
                              ".....????",
                              "?????????",
                              "?????????",
                          }));
  memory.update(openScan(Cell{3, 2}, 9, 7, obstacle));  // east: column 0 leaves the window
  memory.update(openScan(Cell{4, 2}, 9, 7, obstacle));  // east: column 1 leaves, and the obstacle with it
  EXPECT_EQ(draw(memory), (std::vector<std::string>{
                              "??.....??",
                              "??.....??",
                              "??.....??",
                              "??.....??",
                              "??.....??",
                              "?????????",
                              "?????????",
                          }));
  memory.update(openScan(Cell{4, 3}, 9, 7, obstacle));
  memory.update(openScan(Cell{4, 4}, 9, 7, obstacle));  // south twice: rows 0 and 1 leave
  EXPECT_EQ(draw(memory), (std::vector<std::string>{
                              "?????????",
                              "?????????",
                              "??.....??",
                              "??.....??",
                              "??.....??",
                              "??.....??",
                              "??.....??",
                          }));
  memory.update(openScan(Cell{3, 4}, 9, 7, obstacle));  // west: column 6 leaves, the obstacle is seen again
  EXPECT_EQ(draw(memory), (std::vector<std::string>{
                              "?????????",
                              "?????????",
                              "?.....???",
                              "?#....???",
                              "?.....???",
                              "?.....???",
                              "?.....???",
                          }));
}

TEST(AgentMemoryTest, WindowSmallerThanTheScanKeepsOnlyTheWindow) {
  AgentMemory memory;
  memory.reset(6, 6, 3);
  memory.update(openScan(Cell{3, 3}, 6, 6, Cell{1, 1}));  // (1,1) is two cells away: outside a 3x3 window
  EXPECT_EQ(draw(memory), (std::vector<std::string>{
                              "??????",
                              "??????",
                              "??...?",
                              "??...?",
                              "??...?",
                              "??????",
                          }));
}

TEST(AgentMemoryTest, IncrementalForgettingMatchesForgettingEverythingOutsideTheWindow) {
  // Against a brute-force reference (write the scan, then clear every cell outside the window) on random
  // scans along a random walk with occasional jumps, for several windows (0: full memory), on a small map
  // and on one 130 cells wide, whose rows span three words of the bit planes; range 7 scans with full
  // memory, range 2 with a window.
  for (const Cell size : {Cell{11, 8}, Cell{130, 6}}) {
    for (int window : {0, 1, 3, 5, 7}) {
      const int range = window == 0 ? kMaxSensorRange : 2;  // full memory: 15 x 15 scans across word boundaries
      const int side = 2 * range + 1;
      Rng rng(static_cast<std::uint64_t>(window));
      const int width = size.x;
      const int height = size.y;
      AgentMemory memory;
      memory.reset(width, height, window);
      std::vector<std::int8_t> reference(static_cast<std::size_t>(width) * height, kScanUnknown);
      Cell position{5, 4};
      for (int step = 0; step < 40 * width; ++step) {
        if (rng.below(20) == 0) {
          position = Cell{static_cast<int>(rng.below(width)), static_cast<int>(rng.below(height))};
        } else {
          const Cell next{position.x + static_cast<int>(rng.below(3)) - 1, position.y};
          const Cell next2{next.x, next.y + static_cast<int>(rng.below(3)) - 1};
          if (next2.x >= 0 && next2.y >= 0 && next2.x < width && next2.y < height) position = next2;
        }
        std::vector<std::int8_t> cells;
        const std::int8_t values[4] = {kScanFree, kScanObstacle, kScanUnknown, kScanFree};
        for (int dy = -range; dy <= range; ++dy) {
          for (int dx = -range; dx <= range; ++dx) {
            const Cell c{position.x + dx, position.y + dy};
            const bool on_map = c.x >= 0 && c.y >= 0 && c.x < width && c.y < height;
            cells.push_back(on_map ? values[rng.below(4)] : kScanOutOfBounds);
          }
        }
        memory.update(Scan(range, cells, position, Cell{0, 0}, false, step));
        for (int dy = -range; dy <= range; ++dy) {
          for (int dx = -range; dx <= range; ++dx) {
            const Cell c{position.x + dx, position.y + dy};
            const std::int8_t v = cells[(dy + range) * side + (dx + range)];
            if (v == kScanFree || v == kScanObstacle) reference[c.y * width + c.x] = v;
          }
        }
        for (int y = 0; y < height && window > 0; ++y) {
          for (int x = 0; x < width; ++x) {
            if (std::abs(x - position.x) > window / 2 || std::abs(y - position.y) > window / 2) {
              reference[y * width + x] = kScanUnknown;
            }
          }
        }
        for (int y = 0; y < height; ++y) {
          for (int x = 0; x < width; ++x) {
            ASSERT_EQ(memory.at(Cell{x, y}), reference[y * width + x])
                << "width " << width << " window " << window << " step " << step << " cell (" << x << "," << y
                << ")";
          }
        }
      }
    }
  }
}

TEST(AgentMemoryTest, ALimitOfRecentScansForgetsWhatOnlyOlderScansSaw) {
  // An open 9x5 map, scans of range 2 at x = 2, 4, 6 on row 2, keeping the last two scans.
  AgentMemory memory;
  memory.reset(9, 5, 0, 2);
  memory.update(openScan(Cell{2, 2}, 9, 5, Cell{0, 0}));  // columns 0-4, (0,0) an obstacle
  EXPECT_EQ(draw(memory), (std::vector<std::string>{"#....????", ".....????", ".....????", ".....????",
                                                    ".....????"}));
  memory.update(openScan(Cell{4, 2}, 9, 5, Cell{-1, -1}));  // columns 2-6
  EXPECT_EQ(draw(memory), (std::vector<std::string>{"#......??", ".......??", ".......??", ".......??",
                                                    ".......??"}));
  // The third scan (columns 4-8) pushes the first out: columns 0-1 only it saw are forgotten; 2-3 the second
  // scan saw too, and stay.
  memory.update(openScan(Cell{6, 2}, 9, 5, Cell{-1, -1}));
  EXPECT_EQ(draw(memory), (std::vector<std::string>{"??.......", "??.......", "??.......", "??.......",
                                                    "??......."}));
  // Standing still, the fourth scan pushes the second out: columns 2-3 go, what the third and fourth saw stays.
  memory.update(openScan(Cell{6, 2}, 9, 5, Cell{-1, -1}));
  EXPECT_EQ(draw(memory), (std::vector<std::string>{"????.....", "????.....", "????.....", "????.....",
                                                    "????....."}));
  // A limit of one scan keeps the current scan only.
  memory.reset(9, 5, 0, 1);
  memory.update(openScan(Cell{2, 2}, 9, 5, Cell{0, 0}));
  memory.update(openScan(Cell{3, 2}, 9, 5, Cell{-1, -1}));
  EXPECT_EQ(draw(memory), (std::vector<std::string>{"?.....???", "?.....???", "?.....???", "?.....???",
                                                    "?.....???"}));
}

TEST(AgentMemoryTest, ResetForgetsEverything) {
  AgentMemory memory;
  memory.reset(3, 3, 0);
  memory.update(drawnScan(Cell{1, 1}, {"...", ".#.", "..."}));
  memory.reset(4, 2, 0);
  EXPECT_EQ(draw(memory), (std::vector<std::string>{"????", "????"}));
}

}  // namespace
}  // namespace agents
}  // namespace ppp
