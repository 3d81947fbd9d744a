#include "ppp_core/window_mask.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/window_atlas.hpp"

namespace ppp {
namespace {

TEST(WindowMaskTest, WordsPerWindowFollowTheCellCount) {
  EXPECT_EQ(windowWords(1), 1);  // 9 cells
  EXPECT_EQ(windowWords(3), 1);  // 49
  EXPECT_EQ(windowWords(4), 2);  // 81
  EXPECT_EQ(windowWords(7), 4);  // 225
  EXPECT_EQ(windowWords(kMaxSensorRange), kMaxWindowWords);
}

TEST(WindowMaskTest, EverySensedWindowComesBackFromItsMasks) {
  // Every cell of noisy scans of random maps, at a one-word range and a four-word one: packing then unpacking
  // gives the sensor's own window, its off-map cells included (an off-map cell behind an obstacle is unknown).
  for (int range : {2, 7}) {
    Rng rng(5);
    const SensorModel sensor(SensorOptions{range, 0.2});
    const int cells = (2 * range + 1) * (2 * range + 1);
    for (int trial = 0; trial < 10; ++trial) {
      Grid g(9, 13);
      for (int i = 0; i < g.size(); ++i) g.setObstacle(g.cellAt(i), rng.bernoulli(0.3));
      for (int i = 0; i < g.size(); ++i) {
        std::vector<std::int8_t> window(cells);
        sensor.scan(g, g.cellAt(i), rng.next(), trial, window.data());
        std::array<std::uint64_t, kMaxWindowWords> free{}, obstacle{};
        packWindow(window.data(), range, free.data(), obstacle.data());
        std::vector<std::int8_t> back(cells, 42);
        unpackWindow(free.data(), obstacle.data(), range, back.data());
        ASSERT_EQ(back, window) << "range " << range << " trial " << trial << " cell " << i;
      }
    }
  }
}

TEST(WindowMaskTest, CellsLandOnTheirBits) {
  // Range 1 by hand: cells 0-2 off the map (both bits), 4 an obstacle, 8 unknown (neither), the rest free.
  const std::vector<std::int8_t> window{kScanOutOfBounds, kScanOutOfBounds, kScanOutOfBounds, kScanFree, kScanObstacle,
                                        kScanFree,        kScanFree,        kScanFree,        kScanUnknown};
  std::uint64_t free = 0, obstacle = 0;
  packWindow(window.data(), 1, &free, &obstacle);
  EXPECT_EQ(free, 0b011101111u);
  EXPECT_EQ(obstacle, 0b000010111u);
  std::vector<std::int8_t> back(9);
  unpackWindow(&free, &obstacle, 1, back.data());
  EXPECT_EQ(back, window);
  // The same as one-word masks, and the atlas's WindowBits.
  const WindowBits bits = unpackWindow(free, obstacle);
  EXPECT_EQ(bits.free, 0b011101000u);
  EXPECT_EQ(bits.obstacle, 0b000010000u);
  EXPECT_EQ(bits.off_map, 0b000000111u);
  std::uint64_t free_again = 0, obstacle_again = 0;
  packWindow(bits, &free_again, &obstacle_again);
  EXPECT_EQ(free_again, free);
  EXPECT_EQ(obstacle_again, obstacle);
}

TEST(WindowMaskTest, AScanFromMasksReadsAsTheAtlasScanItCameFrom) {
  // Every cell of a noisy sensor's atlas scans: the masks sent (packWindow of Scan::bits) make a scan whose cells
  // (read one at a time or all at once) and masks are the sent scan's.
  Rng rng(9);
  const SensorModel sensor(SensorOptions{2, 0.1});
  Grid g(8, 6);
  for (int i = 0; i < g.size(); ++i) g.setObstacle(g.cellAt(i), rng.bernoulli(0.3));
  const WindowAtlas atlas(g, 2);
  for (int i = 0; i < g.size(); ++i) {
    const Scan sent(sensor, g, g.cellAt(i), Cell{7, 5}, i % 3 == 0, i, rng.next(), &atlas);
    WindowBits bits;
    ASSERT_TRUE(sent.bits(&bits));
    std::uint64_t free = 0, obstacle = 0;
    packWindow(bits, &free, &obstacle);
    const Scan received(2, unpackWindow(free, obstacle), g.cellAt(i), Cell{7, 5}, i % 3 == 0, i);
    for (int dy = -2; dy <= 2; ++dy) {
      for (int dx = -2; dx <= 2; ++dx) ASSERT_EQ(received.at(dx, dy), sent.at(dx, dy)) << i << ": " << dx << "," << dy;
    }
    for (int k = 0; k < 25; ++k) ASSERT_EQ(received.cells()[k], sent.cells()[k]) << i << ": cell " << k;
    WindowBits back;
    ASSERT_TRUE(received.bits(&back));
    EXPECT_EQ(back.free, bits.free);
    EXPECT_EQ(back.obstacle, bits.obstacle);
    EXPECT_EQ(back.off_map, bits.off_map);
    EXPECT_EQ(received.bumped(), sent.bumped());
    EXPECT_EQ(received.step(), i);
  }
}

TEST(WindowMaskTest, AMaskScanRefusesWindowsOfMoreThanOneWord) {
  try {
    const Scan scan(4, WindowBits{}, Cell{0, 0}, Cell{1, 1}, false, 0);
    FAIL() << "range 4 (81 cells) accepted as one mask";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "range");
  }
}

}  // namespace
}  // namespace ppp
