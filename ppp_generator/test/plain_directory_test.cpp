// A plain directory of PPP files (a corpus, a user's suite) read as a set: every .ppp, map_server .yaml and
// MovingAI .map file in file-name order, each PPP named by its file's stem.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/ppp_file.hpp"
#include "ppp_core/problem_io.hpp"
#include "ppp_generator/problem_set.hpp"

namespace ppp {
namespace generator {
namespace {

namespace fs = std::filesystem;

std::string tempDir() {
  char name[] = "/tmp/ppp_plain_directory_test_XXXXXX";
  const char* made = mkdtemp(name);
  EXPECT_NE(made, nullptr);
  return made;
}

Problem barProblem(int x) {
  Problem p = Problem::empty(6, 6, 4);
  p.obstacles.push_back(Obstacle{Shape::VerticalBar, x, 1, 3, 1});
  return p;
}

TEST(PlainDirectoryTest, ReadsEveryMapFileInFileNameOrderNamedByItsStem) {
  const std::string dir = tempDir();
  writePppFile(barProblem(2), dir + "/b_trap.ppp");
  writeProblemFile(barProblem(3), dir + "/a_site.map");   // MovingAI: the first and last free cells are start, goal
  writeProblemFile(barProblem(4), dir + "/c_floor.yaml");  // map_server, with its .pgm beside it
  std::ofstream(dir + "/notes.txt") << "not a map\n";
  const std::vector<std::string> files = problemSetFiles(dir);
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(fs::path(files[0]).filename(), "a_site.map");
  EXPECT_EQ(fs::path(files[1]).filename(), "b_trap.ppp");
  EXPECT_EQ(fs::path(files[2]).filename(), "c_floor.yaml");

  const ProblemSet set = readProblemSetDirectory(dir);
  EXPECT_EQ(set.ids, (std::vector<std::string>{"a_site", "b_trap", "c_floor"}));
  ASSERT_EQ(set.problems.size(), 3u);
  // The .map holds cells only, so it comes back as one descriptor per run of obstacle cells, on the same grid.
  EXPECT_EQ(decodeGrid(set.problems[0]), decodeGrid(barProblem(3)));
  EXPECT_EQ(set.problems[0].start, (Cell{0, 0}));
  EXPECT_EQ(set.problems[0].goal, (Cell{5, 5}));
  EXPECT_EQ(set.problems[1].obstacles, barProblem(2).obstacles);
  EXPECT_EQ(decodeGrid(set.problems[2]), decodeGrid(barProblem(4)));
  EXPECT_EQ(set.fitness, "");  // no metadata: no fitness
  EXPECT_EQ(set.fitness_values, (std::vector<double>{0, 0, 0}));
  EXPECT_EQ(set.evaluations.size(), 3u);
  fs::remove_all(dir);
}

TEST(PlainDirectoryTest, KeepsTheFitnessEveryPppCarries) {
  const std::string dir = tempDir();
  for (const auto& [name, value] : {std::pair<const char*, const char*>{"x", "0.5"}, {"y", "1"}}) {
    Problem p = barProblem(2);
    setMetadata(&p.metadata, "fitness", "failure");
    setMetadata(&p.metadata, "fitness_value", value);
    writePppFile(p, dir + "/" + name + ".ppp");
  }
  ProblemSet set = readProblemSetDirectory(dir);
  EXPECT_EQ(set.fitness, "failure");
  EXPECT_TRUE(set.maximise);
  EXPECT_EQ(set.fitness_values, (std::vector<double>{0.5, 1.0}));

  writePppFile(barProblem(3), dir + "/z.ppp");  // one PPP without a fitness: the set has none
  set = readProblemSetDirectory(dir);
  EXPECT_EQ(set.fitness, "");
  EXPECT_EQ(set.fitness_values, (std::vector<double>{0, 0, 0}));
  fs::remove_all(dir);
}

TEST(PlainDirectoryTest, RefusesTwoFilesOfOneNameAndADirectoryWithoutAPpp) {
  const std::string dir = tempDir();
  try {
    problemSetFiles(dir);
    ADD_FAILURE() << "an empty directory was read";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(dir + ": holds no PPP: no .ppp, map_server .yaml or MovingAI .map file"),
              std::string::npos)
        << e.what();
  }
  writePppFile(barProblem(2), dir + "/same.ppp");
  writeProblemFile(barProblem(3), dir + "/same.map");
  try {
    readProblemSetDirectory(dir);
    ADD_FAILURE() << "two PPPs named 'same' were read";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("same.ppp:0: file: a second PPP named 'same'"), std::string::npos) << e.what();
  }
  try {
    problemSetFiles(dir + "/missing");
    ADD_FAILURE() << "a missing directory was listed";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("missing: is not a directory of PPP files"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace generator
}  // namespace ppp
