#include "ppp_core/octomap_export.hpp"

#include <gtest/gtest.h>
#include <octomap/OcTree.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/map_frame.hpp"
#include "ppp_core/random_problem.hpp"

namespace ppp {
namespace {

namespace fs = std::filesystem;

std::string tempPath(const std::string& name) {
  return (fs::temp_directory_path() / ("ppp_octomap_test_" + std::to_string(::getpid()) + "_" + name)).string();
}

/// 4x3 with an hbar over the top-left two cells; start bottom-left, goal bottom-right:
///   ##..
///   ....
///   S..G
Problem topLeftBar() {
  Problem p = Problem::empty(4, 3, 1);
  p.start = Cell{0, 2};
  p.goal = Cell{3, 2};
  p.obstacles = {{Shape::HorizontalBar, 0, 0, 2, 1}};
  return p;
}

/// "occupied", "free" or "unknown" for the voxel at a map-frame point.
std::string stateAt(const octomap::OcTree& tree, double x, double y, double z) {
  const octomap::OcTreeNode* node = tree.search(x, y, z);
  if (node == nullptr) return "unknown";
  return tree.isNodeOccupied(node) ? "occupied" : "free";
}

TEST(OctomapExportTest, ObstaclesAreExtrudedAndFreeSpaceIsKnown) {
  const std::string path = tempPath("bar.bt");
  OctomapOptions options;
  options.resolution = 0.5;
  options.height = 1.0;  // two voxel layers
  writeOctomap(topLeftBar(), path, options);
  const octomap::OcTree tree(path);
  EXPECT_DOUBLE_EQ(tree.getResolution(), 0.5);

  // Grid (0, 0) is the top-left cell: in the map frame (y up) its centre is at y = (H - 0.5) * res.
  EXPECT_EQ(stateAt(tree, 0.25, (3 - 0.5) * 0.5, 0.25), "occupied");
  EXPECT_EQ(stateAt(tree, 0.25, 1.25, 0.75), "occupied");
  EXPECT_EQ(stateAt(tree, 0.75, 1.25, 0.75), "occupied");  // grid (1, 0)
  // Grid (0, 2), the bottom-left start cell, sits at map y = 0.25 and is free, not the obstacle.
  EXPECT_EQ(stateAt(tree, 0.25, 0.25, 0.25), "free");
  EXPECT_EQ(stateAt(tree, 0.25, 0.25, 0.75), "free");
  EXPECT_EQ(stateAt(tree, 1.25, 1.25, 0.25), "free");  // grid (2, 0)
  EXPECT_EQ(stateAt(tree, 1.75, 0.75, 0.75), "free");  // grid (3, 1)
  // Nothing above the extrusion or outside the grid.
  EXPECT_EQ(stateAt(tree, 0.25, 1.25, 1.25), "unknown");
  EXPECT_EQ(stateAt(tree, -0.25, 0.25, 0.25), "unknown");
  EXPECT_EQ(stateAt(tree, 0.25, 1.75, 0.25), "unknown");
  fs::remove(path);
}

TEST(OctomapExportTest, HeightIsRoundedUpToWholeVoxels) {
  const std::string path = tempPath("tall.bt");
  OctomapOptions options;
  options.resolution = 0.5;
  options.height = 1.2;  // three layers: 0..1.5 m
  writeOctomap(topLeftBar(), path, options);
  const octomap::OcTree tree(path);
  EXPECT_EQ(stateAt(tree, 0.25, 1.25, 1.25), "occupied");
  EXPECT_EQ(stateAt(tree, 0.25, 0.25, 1.25), "free");
  EXPECT_EQ(stateAt(tree, 0.25, 1.25, 1.75), "unknown");
  fs::remove(path);
}

TEST(OctomapExportTest, EveryCellMatchesTheGridAtEveryLayer) {
  Rng rng(99);
  const Problem p = randomProblem(rng, Problem::empty(13, 9, 8), 8);
  const std::string path = tempPath("random.bt");
  OctomapOptions options;
  options.resolution = 0.2;
  options.height = 0.6;
  writeOctomap(p, path, options);
  const octomap::OcTree tree(path);
  const Grid grid = decodeGrid(p);
  const MapFrame frame{p.width, p.height, options.resolution};
  for (int y = 0; y < p.height; ++y) {
    for (int x = 0; x < p.width; ++x) {
      const Cell c{x, y};
      for (double z : {0.1, 0.3, 0.5}) {
        EXPECT_EQ(stateAt(tree, frame.centreX(c), frame.centreY(c), z), grid.isObstacle(c) ? "occupied" : "free")
            << "cell (" << x << ", " << y << ") z " << z;
      }
    }
  }
  fs::remove(path);
}

TEST(OctomapExportTest, BadOptionsAndPathsAreRefused) {
  const Problem p = topLeftBar();
  const std::string path = tempPath("bad.bt");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double height : {0.0, -1.0, nan}) {
    OctomapOptions options;
    options.height = height;
    try {
      writeOctomap(p, path, options);
      ADD_FAILURE() << "accepted height " << height;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.name(), "height");
    }
  }
  for (double resolution : {0.0, -0.5, nan}) {
    OctomapOptions options;
    options.resolution = resolution;
    try {
      writeOctomap(p, path, options);
      ADD_FAILURE() << "accepted resolution " << resolution;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.name(), "resolution");
    }
  }
  OctomapOptions beyond_keys;
  beyond_keys.resolution = 0.001;
  beyond_keys.height = 1000.0;  // a million layers; OctoMap keys reach 32768
  EXPECT_THROW(writeOctomap(p, path, beyond_keys), InvalidArgument);
  OctomapOptions two_metres;
  two_metres.height = 2.0;  // 4096 x 4096 x 2 voxels
  EXPECT_THROW(writeOctomap(Problem::empty(4096, 4096, 0), path, two_metres), InvalidArgument);
  EXPECT_FALSE(fs::exists(path));
  try {
    writeOctomap(p, "/nonexistent/dir/map.bt");
    ADD_FAILURE() << "wrote into a missing directory";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/map.bt"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ppp
