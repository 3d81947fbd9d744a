#include "ppp_msgs/conversions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/rng.hpp"

namespace {

static_assert(ppp_msgs::Obstacle::HBAR == static_cast<int>(ppp::Shape::HorizontalBar), "shape order");
static_assert(ppp_msgs::Obstacle::VBAR == static_cast<int>(ppp::Shape::VerticalBar), "shape order");
static_assert(ppp_msgs::Obstacle::DIAG_DOWN == static_cast<int>(ppp::Shape::DiagonalDown), "shape order");
static_assert(ppp_msgs::Obstacle::DIAG_UP == static_cast<int>(ppp::Shape::DiagonalUp), "shape order");
static_assert(ppp_msgs::Obstacle::BLOCK == static_cast<int>(ppp::Shape::Block), "shape order");

struct Size {
  int width;
  int height;
};

/// Non-square sizes on purpose: a swapped width/height or a missed flip cannot pass them.
const Size kSizes[] = {{20, 20}, {7, 13}, {31, 5}, {2, 3}, {3, 2}, {50, 17}, {12, 40}};

/// Random valid problems of every size, some with start and goal away from the corners, with metadata.
std::vector<ppp::Problem> randomProblems(std::uint64_t seed, int per_size) {
  ppp::Rng rng(seed);
  std::vector<ppp::Problem> problems;
  for (const Size& size : kSizes) {
    for (int n = 0; n < per_size; ++n) {
      ppp::Problem shape = ppp::Problem::empty(size.width, size.height, 12);
      if (n % 2 == 1) {
        shape.start = ppp::Cell{static_cast<int>(rng.below(size.width)), static_cast<int>(rng.below(size.height))};
        do {
          shape.goal = ppp::Cell{static_cast<int>(rng.below(size.width)), static_cast<int>(rng.below(size.height))};
        } while (shape.goal == shape.start);
      }
      const int count = static_cast<int>(rng.below(static_cast<std::uint64_t>(shape.max_obstacles) + 1));
      ppp::Problem problem = ppp::randomProblem(rng, shape, count);
      ppp::setMetadata(&problem.metadata, "fitness", "difficulty");
      ppp::setMetadata(&problem.metadata, "seed", std::to_string(seed));
      ppp::setMetadata(&problem.metadata, "index", std::to_string(problems.size()));
      problems.push_back(problem);
    }
  }
  return problems;
}

/// Runs `action`, expects ppp::InvalidArgument naming exactly `field`, and returns its message.
template <typename Action>
std::string expectInvalid(Action action, const std::string& field) {
  try {
    action();
  } catch (const ppp::InvalidArgument& e) {
    EXPECT_EQ(e.name(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "expected ppp::InvalidArgument naming " << field;
  return "";
}

/// A valid 5x4 problem with a known genotype: a vertical bar in column 2, rows 0..2.
ppp::Problem smallProblem() {
  ppp::Problem problem = ppp::Problem::empty(5, 4, 3);
  problem.obstacles.push_back(ppp::Obstacle{ppp::Shape::VerticalBar, 2, 0, 3, 1});
  return problem;
}

TEST(ToOccupancyGrid, HeaderInfoAndOrigin) {
  ppp::Grid grid(7, 3);
  const nav_msgs::OccupancyGrid map = ppp_msgs::toOccupancyGrid(grid, 0.25);
  EXPECT_EQ(map.header.frame_id, "map");
  EXPECT_EQ(map.info.width, 7u);
  EXPECT_EQ(map.info.height, 3u);
  EXPECT_FLOAT_EQ(map.info.resolution, 0.25f);
  EXPECT_EQ(map.info.origin.position.x, 0.0);
  EXPECT_EQ(map.info.origin.position.y, 0.0);
  EXPECT_EQ(map.info.origin.position.z, 0.0);
  EXPECT_EQ(map.info.origin.orientation.x, 0.0);
  EXPECT_EQ(map.info.origin.orientation.y, 0.0);
  EXPECT_EQ(map.info.origin.orientation.z, 0.0);
  EXPECT_EQ(map.info.origin.orientation.w, 1.0);
  EXPECT_EQ(map.data.size(), 21u);
  EXPECT_EQ(ppp_msgs::toOccupancyGrid(grid, 1.0, "world").header.frame_id, "world");
}

TEST(ToOccupancyGrid, TopLeftGridCellIsFirstCellOfLastMapRow) {
  ppp::Grid grid(3, 2);
  grid.setObstacle(ppp::Cell{0, 0}, true);
  const nav_msgs::OccupancyGrid map = ppp_msgs::toOccupancyGrid(grid, 1.0);
  const std::vector<std::int8_t> expected = {0, 0, 0, 100, 0, 0};
  EXPECT_EQ(map.data, expected);
}

TEST(ToOccupancyGrid, BottomRightGridCellIsLastCellOfFirstMapRow) {
  ppp::Grid grid(3, 2);
  grid.setObstacle(ppp::Cell{2, 1}, true);
  const std::vector<std::int8_t> expected = {0, 0, 100, 0, 0, 0};
  EXPECT_EQ(ppp_msgs::toOccupancyGrid(grid, 1.0).data, expected);
}

TEST(ToOccupancyGrid, AFinerMapDrawsEachCellAsABlockAtTheSameMetres) {
  // Cells y down: row 0 = {obstacle, free}, row 1 = {unknown, free}; two map cells per cell side, 0.5 m each.
  const std::vector<std::int8_t> cells = {100, 0, -1, 0};
  const nav_msgs::OccupancyGrid map = ppp_msgs::toFinerOccupancyGrid(cells, 2, 2, 1.0, 2, "map");
  EXPECT_EQ(map.info.width, 4u);
  EXPECT_EQ(map.info.height, 4u);
  EXPECT_FLOAT_EQ(map.info.resolution, 0.5f);
  // Map rows bottom first: the unknown cell (bottom-left in metres) fills map rows 0-1, columns 0-1.
  const std::vector<std::int8_t> expected = {-1, -1, 0, 0,   -1, -1, 0, 0,
                                             100, 100, 0, 0, 100, 100, 0, 0};
  EXPECT_EQ(map.data, expected);
  EXPECT_EQ(ppp_msgs::toFinerOccupancyGrid(cells, 2, 2, 1.0, 1, "map").data,
            ppp_msgs::toOccupancyGrid(cells, 2, 2, 1.0, "map").data);
  EXPECT_THROW(ppp_msgs::toFinerOccupancyGrid(cells, 2, 2, 1.0, 0, "map"), ppp::InvalidArgument);
  EXPECT_THROW(ppp_msgs::toFinerOccupancyGrid(cells, 2, 2, 1.0, 17, "map"), ppp::InvalidArgument);
}

TEST(ToOccupancyGrid, EveryCellLandsAtTheFlippedIndex) {
  for (const ppp::Problem& problem : randomProblems(11, 3)) {
    const ppp::Grid grid = ppp::decodeGrid(problem);
    const nav_msgs::OccupancyGrid map = ppp_msgs::toOccupancyGrid(grid, 0.5);
    const int w = grid.width();
    const int h = grid.height();
    ASSERT_EQ(map.data.size(), static_cast<std::size_t>(w * h));
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t flipped = static_cast<std::size_t>((h - 1 - y) * w + x);
        EXPECT_EQ(map.data[flipped], grid.isObstacle(ppp::Cell{x, y}) ? 100 : 0)
            << "grid cell (" << x << ", " << y << ") of " << w << "x" << h;
      }
    }
    EXPECT_EQ(ppp_msgs::fromOccupancyGrid(map), grid);
  }
}

TEST(ToOccupancyGrid, RejectsBadResolutionAndEmptyGrid) {
  const ppp::Grid grid(4, 4);
  expectInvalid([&] { ppp_msgs::toOccupancyGrid(grid, 0.0); }, "resolution");
  expectInvalid([&] { ppp_msgs::toOccupancyGrid(grid, -1.0); }, "resolution");
  expectInvalid([&] { ppp_msgs::toOccupancyGrid(ppp::Grid(), 1.0); }, "grid");
}

TEST(FromOccupancyGrid, Thresholds) {
  nav_msgs::OccupancyGrid map = ppp_msgs::toOccupancyGrid(ppp::Grid(3, 2), 1.0);
  map.data = {0, 49, 50, -1, 100, 1};
  const ppp::Grid grid = ppp_msgs::fromOccupancyGrid(map);
  // Map row 0 (bottom) is grid row 1.
  EXPECT_FALSE(grid.isObstacle(ppp::Cell{0, 1}));  // 0
  EXPECT_FALSE(grid.isObstacle(ppp::Cell{1, 1}));  // 49
  EXPECT_TRUE(grid.isObstacle(ppp::Cell{2, 1}));   // 50
  EXPECT_TRUE(grid.isObstacle(ppp::Cell{0, 0}));   // -1 unknown
  EXPECT_TRUE(grid.isObstacle(ppp::Cell{1, 0}));   // 100
  EXPECT_FALSE(grid.isObstacle(ppp::Cell{2, 0}));  // 1
}

TEST(FromOccupancyGrid, RejectsMalformedMaps) {
  const nav_msgs::OccupancyGrid good = ppp_msgs::toOccupancyGrid(ppp::Grid(4, 3), 1.0);

  nav_msgs::OccupancyGrid map = good;
  map.data.pop_back();
  const std::string message = expectInvalid([&] { ppp_msgs::fromOccupancyGrid(map); }, "map.data");
  EXPECT_NE(message.find("12"), std::string::npos) << message;
  EXPECT_NE(message.find("11"), std::string::npos) << message;

  map = good;
  map.data.push_back(0);
  expectInvalid([&] { ppp_msgs::fromOccupancyGrid(map); }, "map.data");

  map = good;
  map.info.width = 0;
  expectInvalid([&] { ppp_msgs::fromOccupancyGrid(map); }, "map.info.width");

  map = good;
  map.info.width = static_cast<std::uint32_t>(-1);  // a negative width wraps in the uint32 field
  expectInvalid([&] { ppp_msgs::fromOccupancyGrid(map); }, "map.info.width");

  map = good;
  map.info.width = ppp::kMaxGridSide + 1;
  expectInvalid([&] { ppp_msgs::fromOccupancyGrid(map); }, "map.info.width");

  map = good;
  map.info.height = 0;
  expectInvalid([&] { ppp_msgs::fromOccupancyGrid(map); }, "map.info.height");

  map = good;
  map.info.height = static_cast<std::uint32_t>(-3);
  expectInvalid([&] { ppp_msgs::fromOccupancyGrid(map); }, "map.info.height");

  map = good;
  map.info.resolution = 0.0f;
  expectInvalid([&] { ppp_msgs::fromOccupancyGrid(map); }, "map.info.resolution");

  map = good;
  map.info.resolution = -0.05f;
  expectInvalid([&] { ppp_msgs::fromOccupancyGrid(map); }, "map.info.resolution");

  map = good;
  map.data[5] = -2;
  expectInvalid([&] { ppp_msgs::fromOccupancyGrid(map); }, "map.data[5]");

  map = good;
  map.data[7] = 101;
  expectInvalid([&] { ppp_msgs::fromOccupancyGrid(map); }, "map.data[7]");
}

TEST(ProblemMessage, StartAndGoalAreMapFrameIndices) {
  ppp::Problem problem = smallProblem();
  problem.start = ppp::Cell{1, 0};
  problem.goal = ppp::Cell{4, 3};
  const ppp_msgs::Problem message = ppp_msgs::toMessage(problem, "p1", 0.5);
  EXPECT_EQ(message.id, "p1");
  EXPECT_EQ(message.start.x, 1);
  EXPECT_EQ(message.start.y, 3);  // grid row 0 (top) is map row H-1 = 3
  EXPECT_EQ(message.goal.x, 4);
  EXPECT_EQ(message.goal.y, 0);  // grid row 3 (bottom) is map row 0
  EXPECT_EQ(message.map.header.frame_id, "map");
  EXPECT_EQ(message.map.info.width, 5u);
  EXPECT_EQ(message.map.info.height, 4u);
  EXPECT_EQ(message.max_obstacles, 3u);
  ASSERT_EQ(message.obstacles.size(), 1u);
  // The genotype keeps grid (y-down) coordinates.
  EXPECT_EQ(message.obstacles[0].shape, ppp_msgs::Obstacle::VBAR);
  EXPECT_EQ(message.obstacles[0].x, 2);
  EXPECT_EQ(message.obstacles[0].y, 0);
  EXPECT_EQ(message.obstacles[0].length, 3);
  EXPECT_EQ(message.obstacles[0].height, 1);
  // The bar covers grid rows 0..2 of column 2, i.e. map rows 3..1; map row 0 stays free there.
  EXPECT_EQ(message.map.data[0 * 5 + 2], 0);
  EXPECT_EQ(message.map.data[1 * 5 + 2], 100);
  EXPECT_EQ(message.map.data[2 * 5 + 2], 100);
  EXPECT_EQ(message.map.data[3 * 5 + 2], 100);
}

TEST(ProblemMessage, RoundTripOnRandomProblems) {
  int checked = 0;
  for (std::uint64_t seed : {1u, 2u, 3u, 42u, 2024u}) {
    for (const ppp::Problem& problem : randomProblems(seed, 6)) {
      const ppp_msgs::Problem message = ppp_msgs::toMessage(problem, "id", 0.1);
      const ppp::Problem back = ppp_msgs::fromMessage(message);
      EXPECT_EQ(back, problem) << "seed " << seed << ", " << problem.width << "x" << problem.height;
      EXPECT_EQ(ppp::decodeGrid(back), ppp_msgs::fromOccupancyGrid(message.map));
      const int h = problem.height;
      EXPECT_EQ(message.start.x, problem.start.x);
      EXPECT_EQ(message.start.y, h - 1 - problem.start.y);
      EXPECT_EQ(message.goal.x, problem.goal.x);
      EXPECT_EQ(message.goal.y, h - 1 - problem.goal.y);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 5 * 6 * static_cast<int>(std::size(kSizes)));
}

TEST(ProblemMessage, MetadataKeepsOrder) {
  ppp::Problem problem = smallProblem();
  problem.metadata = {{"z", "1"}, {"a", "2"}, {"m", ""}};
  const ppp_msgs::Problem message = ppp_msgs::toMessage(problem, "p", 1.0);
  ASSERT_EQ(message.metadata.size(), 3u);
  EXPECT_EQ(message.metadata[0].key, "z");
  EXPECT_EQ(message.metadata[1].value, "2");
  EXPECT_EQ(ppp_msgs::fromMessage(message).metadata, problem.metadata);
}

TEST(ProblemMessage, ToMessageRejectsInvalidProblems) {
  ppp::Problem problem = smallProblem();
  expectInvalid([&] { ppp_msgs::toMessage(problem, "p", 0.0); }, "resolution");
  problem.goal = ppp::Cell{5, 0};
  expectInvalid([&] { ppp_msgs::toMessage(problem, "p", 1.0); }, "goal");
}

TEST(ProblemMessage, FromMessageRejectsMapDisagreeingWithGenotype) {
  const ppp_msgs::Problem good = ppp_msgs::toMessage(smallProblem(), "p", 1.0);

  // Grid cell (0, 0), top-left, is map index (4-1-0)*5+0 = 15; it is the start, so free by the genotype.
  ppp_msgs::Problem message = good;
  message.map.data[15] = 100;
  std::string what = expectInvalid([&] { ppp_msgs::fromMessage(message); }, "map.data[15]");
  EXPECT_NE(what.find("(0, 0)"), std::string::npos) << what;

  // Grid cell (2, 1) is covered by the bar: map index (4-1-1)*5+2 = 12.
  message = good;
  message.map.data[12] = 0;
  what = expectInvalid([&] { ppp_msgs::fromMessage(message); }, "map.data[12]");
  EXPECT_NE(what.find("(2, 1)"), std::string::npos) << what;

  // A genotype edit without the matching map edit is caught as well. Moving the bar from column 2 to 3
  // changes grid cells (2..3, 0..2); the first in grid row-major order is (2, 0), map index (4-1-0)*5+2 = 17.
  message = good;
  message.obstacles[0].x = 3;
  what = expectInvalid([&] { ppp_msgs::fromMessage(message); }, "map.data[17]");
  EXPECT_NE(what.find("grid cell (2, 0)"), std::string::npos) << what;
}

TEST(ProblemMessage, FromMessageRejectsBadFields) {
  const ppp_msgs::Problem good = ppp_msgs::toMessage(smallProblem(), "p", 1.0);

  ppp_msgs::Problem message = good;
  message.map.data.resize(3);
  expectInvalid([&] { ppp_msgs::fromMessage(message); }, "map.data");

  message = good;
  message.map.info.width = 0;
  expectInvalid([&] { ppp_msgs::fromMessage(message); }, "map.info.width");

  message = good;
  message.map.info.resolution = 0.0f;
  expectInvalid([&] { ppp_msgs::fromMessage(message); }, "map.info.resolution");

  message = good;
  message.start.y = 4;
  expectInvalid([&] { ppp_msgs::fromMessage(message); }, "start");

  message = good;
  message.goal.x = -1;
  expectInvalid([&] { ppp_msgs::fromMessage(message); }, "goal");

  message = good;
  message.goal = message.start;
  expectInvalid([&] { ppp_msgs::fromMessage(message); }, "goal");

  message = good;
  message.obstacles[0].shape = 5;
  expectInvalid([&] { ppp_msgs::fromMessage(message); }, "obstacles[0].shape");

  message = good;
  message.obstacles[0].x = 99;
  expectInvalid([&] { ppp_msgs::fromMessage(message); }, "obstacles[0]");

  message = good;
  message.max_obstacles = 0;
  expectInvalid([&] { ppp_msgs::fromMessage(message); }, "obstacles");

  message = good;
  message.max_obstacles = static_cast<std::uint32_t>(-1);
  expectInvalid([&] { ppp_msgs::fromMessage(message); }, "max_obstacles");
}

}  // namespace

namespace {

TEST(ToLaserScan, RaysInMetresFromTheWindow) {
  // Range 1 (3x3 window, row-major, y down): an obstacle east of the robot, the rest free.
  const std::vector<std::int8_t> window = {0, 0, 0, 0, 0, 100, 0, 0, 0};
  const sensor_msgs::LaserScan laser = ppp_msgs::toLaserScan(window.data(), 1, 0.5, "explorer/base_link");
  EXPECT_EQ(laser.header.frame_id, "explorer/base_link");
  ASSERT_EQ(laser.ranges.size(), static_cast<std::size_t>(ppp_msgs::kLaserRays));
  EXPECT_FLOAT_EQ(laser.angle_increment, static_cast<float>(2.0 * M_PI / ppp_msgs::kLaserRays));
  EXPECT_FLOAT_EQ(laser.range_max, static_cast<float>(1.5 * std::sqrt(2.0) * 0.5));
  // East (ray 0) meets the obstacle half a cell out: 0.25 m; west (ray 36) leaves the window: no return.
  EXPECT_NEAR(laser.ranges[0], 0.25f, 0.03f);
  EXPECT_TRUE(std::isinf(laser.ranges[ppp_msgs::kLaserRays / 2]));
}

TEST(ToOccupancyGrid, KnownCellsKeepTheirValuesAndTheRowsAreFlipped) {
  // A 2x2 memory, grid rows (y down): top row unknown, free; bottom row obstacle, free.
  const std::vector<std::int8_t> cells{-1, 0, 100, 0};
  const nav_msgs::OccupancyGrid map = ppp_msgs::toOccupancyGrid(cells, 2, 2, 0.5, "map");
  EXPECT_EQ(map.info.width, 2u);
  EXPECT_EQ(map.info.resolution, 0.5f);
  // Map row 0 is the grid's bottom row.
  EXPECT_EQ(map.data, (std::vector<std::int8_t>{100, 0, -1, 0}));
  EXPECT_THROW(ppp_msgs::toOccupancyGrid(std::vector<std::int8_t>(3, 0), 2, 2, 1.0, "map"), ppp::InvalidArgument);
}

TEST(CellTransform, PutsTheChildOnTheCellCentre) {
  const ppp::MapFrame frame{4, 3, 2.0};
  const geometry_msgs::TransformStamped t = ppp_msgs::cellTransform(frame, ppp::Cell{1, 0}, "map", "robot");
  EXPECT_EQ(t.header.frame_id, "map");
  EXPECT_EQ(t.child_frame_id, "robot");
  EXPECT_DOUBLE_EQ(t.transform.translation.x, 3.0);  // column 1: (1 + 0.5) * 2
  EXPECT_DOUBLE_EQ(t.transform.translation.y, 5.0);  // grid row 0 is map row 2: (2 + 0.5) * 2
  EXPECT_DOUBLE_EQ(t.transform.rotation.w, 1.0);
}

TEST(SignatureCounts, SumsTheRunsOfEachSignature) {
  ppp_msgs::ProblemEvaluation e;
  e.signatures = {"missed_route/g16-31/s1/t0/w0e0", "wandering/g4-7/s4-7/t1/w0e0", "missed_route/g16-31/s1/t0/w0e0"};
  e.signature_counts = {2, 3, 4};
  const std::map<std::string, int> counts = ppp_msgs::signatureCounts(e, "/evaluate");
  ASSERT_EQ(counts.size(), 2u);
  EXPECT_EQ(counts.at("missed_route/g16-31/s1/t0/w0e0"), 6);
  EXPECT_EQ(counts.at("wandering/g4-7/s4-7/t1/w0e0"), 3);
}

TEST(SignatureCounts, RefusesListsOfDifferentLengthsAndMalformedSignaturesNamingTheService) {
  ppp_msgs::ProblemEvaluation e;
  e.signatures = {"wandering/g4-7/s4-7/t1/w0e0"};
  e.signature_counts = {1, 2};
  try {
    ppp_msgs::signatureCounts(e, "/evaluate");
    FAIL() << "lists of different lengths accepted";
  } catch (const ppp::IoError& error) {
    EXPECT_NE(std::string(error.what()).find("/evaluate"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("1 failure signatures and 2 counts"), std::string::npos) << error.what();
  }
  e.signatures = {"wandering/g4-7"};
  e.signature_counts = {1};
  try {
    ppp_msgs::signatureCounts(e, "/evaluate");
    FAIL() << "a malformed signature accepted";
  } catch (const ppp::IoError& error) {
    EXPECT_NE(std::string(error.what()).find("'wandering/g4-7'"), std::string::npos) << error.what();
  }
}

}  // namespace
