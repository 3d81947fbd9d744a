#include "ppp_core/window_atlas.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace {

TEST(WindowAtlasTest, EveryCellMatchesTheSensorWithAndWithoutNoise) {
  // Range 2 takes the sensor's bit-mask path, range 5 its list path; noise is added after the lookup.
  for (int range : {2, 5}) {
    Rng rng(11);
    const SensorModel noiseless(SensorOptions{range, 0.0});
    const SensorModel noisy(SensorOptions{range, 0.3});
    const int cells = (2 * range + 1) * (2 * range + 1);
    for (int trial = 0; trial < 20; ++trial) {
      Grid g(11, 7);
      for (int i = 0; i < g.size(); ++i) g.setObstacle(g.cellAt(i), rng.bernoulli(0.3));
      const WindowAtlas atlas(g, range);
      ASSERT_EQ(atlas.cells(), cells);
      for (int i = 0; i < g.size(); ++i) {
        const Cell at = g.cellAt(i);
        std::vector<std::int8_t> expected(cells);
        noiseless.scan(g, at, 0, 0, expected.data());
        ASSERT_EQ(std::vector<std::int8_t>(atlas.window(at), atlas.window(at) + cells), expected)
            << "range " << range << " trial " << trial << " cell " << at.x << "," << at.y;
        const std::uint64_t seed = rng.next();
        noisy.scan(g, at, seed, trial, expected.data());
        std::vector<std::int8_t> looked_up(atlas.window(at), atlas.window(at) + cells);
        noisy.addNoise(seed, trial, looked_up.data());
        ASSERT_EQ(looked_up, expected) << "noisy, range " << range << " trial " << trial;
      }
    }
  }
}

TEST(WindowAtlasTest, ALazyScanReadsTheAtlasWithTheSensorsNoise) {
  Rng rng(5);
  Grid g(8, 8);
  for (int i = 0; i < g.size(); ++i) g.setObstacle(g.cellAt(i), rng.bernoulli(0.25));
  const WindowAtlas atlas(g, 2);
  const SensorModel noisy(SensorOptions{2, 0.2});
  for (int i = 0; i < g.size(); ++i) {
    const Scan computed(noisy, g, g.cellAt(i), Cell{7, 7}, false, i, 99);
    const Scan looked_up(noisy, g, g.cellAt(i), Cell{7, 7}, false, i, 99, &atlas);
    ASSERT_EQ(std::vector<std::int8_t>(looked_up.cells(), looked_up.cells() + 25),
              std::vector<std::int8_t>(computed.cells(), computed.cells() + 25))
        << "cell " << i;
  }
}

TEST(WindowAtlasTest, ScanBitsAreItsCellsAsMasksWithTheSameNoise) {
  Rng rng(8);
  Grid g(9, 9);
  for (int i = 0; i < g.size(); ++i) g.setObstacle(g.cellAt(i), rng.bernoulli(0.3));
  for (int range = 1; range <= kMaxSensorRange; ++range) {
    const WindowAtlas atlas(g, range);
    const int cells = (2 * range + 1) * (2 * range + 1);
    for (double noise : {0.0, 0.3}) {
      const SensorModel sensor(SensorOptions{range, noise});
      for (int i = 0; i < g.size(); ++i) {
        const Scan scan(sensor, g, g.cellAt(i), Cell{8, 8}, false, i, 1234);
        const Scan from_atlas(sensor, g, g.cellAt(i), Cell{8, 8}, false, i, 1234, &atlas);
        WindowBits bits;
        EXPECT_FALSE(scan.bits(&bits));  // no atlas: cells only
        ASSERT_EQ(from_atlas.bits(&bits), cells <= kMaxBitWindowCells) << "range " << range;
        if (cells > kMaxBitWindowCells) continue;
        WindowBits expected;
        for (int c = 0; c < cells; ++c) {
          expected.free |= static_cast<std::uint64_t>(scan.cells()[c] == kScanFree) << c;
          expected.obstacle |= static_cast<std::uint64_t>(scan.cells()[c] == kScanObstacle) << c;
          expected.off_map |= static_cast<std::uint64_t>(scan.cells()[c] == kScanOutOfBounds) << c;
        }
        ASSERT_EQ(bits.free, expected.free) << "range " << range << " noise " << noise << " cell " << i;
        ASSERT_EQ(bits.obstacle, expected.obstacle) << "range " << range << " noise " << noise << " cell " << i;
        ASSERT_EQ(bits.off_map, expected.off_map) << "range " << range << " noise " << noise << " cell " << i;
        // Read in the other order, the cells agree with the masks too (the noise is drawn once per scan).
        const Scan masks_first(sensor, g, g.cellAt(i), Cell{8, 8}, false, i, 1234, &atlas);
        ASSERT_TRUE(masks_first.bits(&bits));
        ASSERT_EQ(std::vector<std::int8_t>(masks_first.cells(), masks_first.cells() + cells),
                  std::vector<std::int8_t>(scan.cells(), scan.cells() + cells));
      }
    }
  }
}

TEST(WindowAtlasTest, SizeIsOneWindowPerCellAndItsMasks) {
  // Windows of up to 64 cells (range 3) are kept as bytes and as three 8-byte masks.
  EXPECT_EQ(WindowAtlas::bytes(Grid(20, 20), 2), 20u * 20 * (25 + 24));
  EXPECT_EQ(WindowAtlas::bytes(Grid(200, 200), 2), 200u * 200 * (25 + 24));
  EXPECT_EQ(WindowAtlas::bytes(Grid(20, 20), 4), 20u * 20 * 81);
  EXPECT_LE(WindowAtlas::bytes(Grid(200, 200), 2), kMaxWindowAtlasBytes);
  EXPECT_GT(WindowAtlas::bytes(Grid(300, 300), 2), kMaxWindowAtlasBytes);  // scanned step by step instead
}

TEST(WindowAtlasTest, BadRangeIsNamed) {
  const Grid g(4, 4);
  try {
    WindowAtlas atlas(g, 0);
    FAIL() << "range 0 accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "sensor_range");
  }
}

}  // namespace
}  // namespace ppp
