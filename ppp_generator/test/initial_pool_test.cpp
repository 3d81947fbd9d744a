#include "ppp_generator/initial_pool.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/ppp_file.hpp"
#include "ppp_generator/genetic_algorithm.hpp"
#include "ppp_generator/map_elites.hpp"

namespace ppp {
namespace generator {
namespace {

namespace fs = std::filesystem;

/// A 10x10 PPP (start top-left, goal bottom-right) with one vertical bar at column `x` from row `y`.
Problem barProblem(int x, int y, int length) {
  Problem problem = Problem::empty(10, 10, 4);
  problem.obstacles.push_back(Obstacle{Shape::VerticalBar, x, y, length, 1});
  return problem;
}

/// Options for 10x10 PPPs with a pool of `population` and no matings, starting from `dir`.
GeneratorOptions poolOptions(const std::string& dir, int population) {
  GeneratorOptions o;
  o.width = o.height = 10;
  o.max_obstacles = 4;
  o.population = population;
  o.matings = 0;
  o.initial_pool = dir;
  return o;
}

/// A fresh, empty directory for one test.
std::string emptyDirectory(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("initial_pool_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

/// Sets of grids, as cells.
using Grids = std::set<std::vector<std::uint8_t>>;

/// The decoded grids of a pool.
Grids gridsOf(const std::vector<Individual>& pool) {
  Grids grids;
  for (const Individual& i : pool) grids.insert(i.grid.cells());
  return grids;
}

std::vector<std::uint8_t> gridOf(const Problem& problem) { return decodeGrid(problem).cells(); }

TEST(InitialPoolTest, TheSearchStartsFromThePoolsFilesInNameOrderAndDrawsTheRest) {
  const std::string dir = emptyDirectory("order");
  // Written out of name order; a repeat of b.ppp's map and a file of another kind are skipped.
  writePppFile(barProblem(5, 2, 6), dir + "/c.ppp");
  writePppFile(barProblem(3, 0, 7), dir + "/a.ppp");
  writePppFile(barProblem(7, 3, 7), dir + "/b.ppp");
  writePppFile(barProblem(7, 3, 7), dir + "/b2.ppp");
  std::ofstream(dir + "/notes.txt") << "not a PPP\n";
  GeneticAlgorithm ga(poolOptions(dir, 5), makeFitness("turns"));
  const std::vector<Individual> pool = ga.run();
  ASSERT_EQ(pool.size(), 5u);
  EXPECT_EQ(pool[0].grid.cells(), gridOf(barProblem(3, 0, 7)));
  EXPECT_EQ(pool[1].grid.cells(), gridOf(barProblem(7, 3, 7)));
  EXPECT_EQ(pool[2].grid.cells(), gridOf(barProblem(5, 2, 6)));
  EXPECT_EQ(gridsOf(pool).size(), 5u);  // two random PPPs, distinct from the three
  // Scored like any member: the bar at column 3 makes the route turn.
  EXPECT_GT(pool[0].value, 0);

  // A pool larger than the population: the first files by name.
  const std::vector<Individual> two = GeneticAlgorithm(poolOptions(dir, 2), makeFitness("turns")).run();
  EXPECT_EQ(gridsOf(two), (Grids{gridOf(barProblem(3, 0, 7)), gridOf(barProblem(7, 3, 7))}));
}

TEST(InitialPoolTest, MapElitesSeedsItsArchiveFromThePool) {
  const std::string dir = emptyDirectory("elites");
  // One bar and three bars: different obstacle counts, so different archive cells.
  Problem three = barProblem(5, 3, 7);
  three.obstacles.push_back(Obstacle{Shape::HorizontalBar, 0, 5, 3, 1});
  three.obstacles.push_back(Obstacle{Shape::HorizontalBar, 7, 1, 2, 1});
  writePppFile(barProblem(3, 0, 7), dir + "/a.ppp");
  writePppFile(three, dir + "/b.ppp");
  GeneratorOptions o = poolOptions(dir, 2);
  o.archive = kMapElitesArchive;
  MapElites search(o, makeFitness("turns"));
  EXPECT_EQ(gridsOf(search.run()), (Grids{gridOf(barProblem(3, 0, 7)), gridOf(three)}));
}

/// The message of the InvalidArgument("initial_pool", ...) that starting from `dir` throws.
std::string poolError(const GeneratorOptions& options) {
  try {
    GeneticAlgorithm(options, makeFitness("turns")).run();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "initial_pool");
    return e.what();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(InitialPoolTest, PppsThatDoNotFitTheGeneratorAreRefusedNamingTheFile) {
  const std::string dir = emptyDirectory("bad");
  const GeneratorOptions o = poolOptions(dir, 4);
  EXPECT_NE(poolError(o).find("holds no PPP: no .ppp, map_server .yaml or MovingAI .map file"), std::string::npos) << poolError(o);

  Problem wide = Problem::empty(12, 10, 4);
  writePppFile(wide, dir + "/wide.ppp");
  std::string message = poolError(o);
  EXPECT_NE(message.find(dir + "/wide.ppp: 12x10 grid, expected the generator's 10x10"), std::string::npos) << message;
  fs::remove(dir + "/wide.ppp");

  Problem moved = barProblem(5, 0, 3);
  moved.start = Cell{1, 1};
  writePppFile(moved, dir + "/moved.ppp");
  message = poolError(o);
  EXPECT_NE(message.find("moved.ppp: start (1, 1), expected the generator's (0, 0)"), std::string::npos) << message;
  fs::remove(dir + "/moved.ppp");

  Problem crowded = Problem::empty(10, 10, 6);
  for (int x = 2; x < 7; ++x) crowded.obstacles.push_back(Obstacle{Shape::VerticalBar, x, 0, 3, 1});
  writePppFile(crowded, dir + "/crowded.ppp");
  message = poolError(o);
  EXPECT_NE(message.find("crowded.ppp: 5 obstacle descriptors, more than max_obstacles 4"), std::string::npos)
      << message;
  fs::remove(dir + "/crowded.ppp");

  // A one-cell gap: solvable for a point, not for a disc of radius 1.
  Problem gap = Problem::empty(10, 10, 4);
  gap.obstacles.push_back(Obstacle{Shape::VerticalBar, 5, 0, 4, 1});
  gap.obstacles.push_back(Obstacle{Shape::VerticalBar, 5, 5, 5, 1});
  gap.start = Cell{1, 1};
  gap.goal = Cell{8, 8};
  writePppFile(gap, dir + "/gap.ppp");
  GeneratorOptions body = o;
  body.robot_radius = 1;
  body.start = Cell{1, 1};
  body.goal = Cell{8, 8};
  message = poolError(body);
  EXPECT_NE(message.find("gap.ppp: the goal is out of reach for the robot (robot_radius 1)"), std::string::npos)
      << message;
  fs::remove(dir + "/gap.ppp");

  std::ofstream(dir + "/broken.ppp") << "ppp 1\nsize 10 ten\n";
  message = poolError(o);
  EXPECT_NE(message.find("broken.ppp:2"), std::string::npos) << message;

  message = poolError(poolOptions(dir + "/missing", 4));
  EXPECT_NE(message.find("initial_pool: " + dir + "/missing: is not a directory of PPP files"), std::string::npos)
      << message;
}

}  // namespace
}  // namespace generator
}  // namespace ppp
