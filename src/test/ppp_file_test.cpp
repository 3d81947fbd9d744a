#include "ppp_core/ppp_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/random_problem.hpp"

namespace ppp {
namespace {

const char* const kSmall =
    "ppp 1\n"
    "size 4 3\n"
    "start 0 0\n"
    "goal 3 2\n"
    "max_obstacles 2\n"
    "obstacles 1\n"
    "vbar 1 0 2\n"
    "grid\n"
    "S#..\n"
    ".#..\n"
    "...G\n"
    "meta fitness turns\n"
    "end\n";

/// Parses `text` and returns the error message; fails the test when it parses.
std::string parseError(const std::string& text) {
  try {
    parsePpp(text, "bad.ppp");
  } catch (const ParseError& e) {
    return e.what();
  }
  ADD_FAILURE() << "parsed without error:\n" << text;
  return "";
}

/// kSmall with the first occurrence of `from` replaced by `to`.
std::string smallWith(const std::string& from, const std::string& to) {
  std::string text = kSmall;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(PppFileTest, ParsesAHandWrittenFile) {
  const Problem p = parsePpp(kSmall, "small.ppp");
  EXPECT_EQ(p.width, 4);
  EXPECT_EQ(p.height, 3);
  EXPECT_EQ(p.goal, (Cell{3, 2}));
  ASSERT_EQ(p.obstacles.size(), 1u);
  EXPECT_EQ(p.obstacles[0], (Obstacle{Shape::VerticalBar, 1, 0, 2, 1}));
  ASSERT_NE(findMetadata(p.metadata, "fitness"), nullptr);
  EXPECT_EQ(*findMetadata(p.metadata, "fitness"), "turns");
  EXPECT_EQ(formatPpp(p), kSmall);
}

TEST(PppFileTest, RandomProblemsRoundTripIdentically) {
  Rng rng(2024);
  for (int i = 0; i < 200; ++i) {
    const int w = static_cast<int>(rng.uniformInt(2, 30));
    const int h = static_cast<int>(rng.uniformInt(2, 30));
    Problem shape = Problem::empty(w, h, 12);
    const int count = static_cast<int>(rng.uniformInt(0, 12));
    Problem p = randomProblem(rng, shape, count);
    setMetadata(&p.metadata, "seed", std::to_string(i));
    setMetadata(&p.metadata, "note", "round trip " + std::to_string(w) + "x" + std::to_string(h));
    const std::string text = formatPpp(p);
    const Problem back = parsePpp(text, "random.ppp");
    EXPECT_EQ(back, p) << text;
    EXPECT_EQ(formatPpp(back), text);
  }
}

TEST(PppFileTest, FileRoundTrip) {
  const auto path = std::filesystem::temp_directory_path() / "ppp_file_test_round_trip.ppp";
  const Problem p = parsePpp(kSmall, "small.ppp");
  writePppFile(p, path.string());
  EXPECT_EQ(readPppFile(path.string()), p);
  std::filesystem::remove(path);
}

TEST(PppFileTest, BadInputNamesFileLineAndField) {
  struct Case {
    std::string text;
    std::string expected;
  };
  const Case cases[] = {
      {"", "bad.ppp:1: magic: empty file"},
      {"hello world\n", "bad.ppp:1: magic: expected 'ppp 1'"},
      {smallWith("ppp 1", "ppp 2"), "bad.ppp:1: version: unsupported version"},
      {"ppp 1\nsize 4 3\nstart 0 0\n", "bad.ppp:4: goal: unexpected end of file"},
      {smallWith("size 4 3", "size four 3"), "bad.ppp:2: size: width must be an integer, got 'four'"},
      {smallWith("size 4 3", "size 4 -3"), "bad.ppp:2: size: expected width and height in [2, 4096], got 4x-3"},
      {smallWith("size 4 3", "size 100000 100000"), "bad.ppp:2: size: expected width and height in [2, 4096]"},
      {smallWith("size 4 3", "size 99999999999 3"), "bad.ppp:2: size: width must be an integer"},
      {smallWith("start 0 0", "start 4 0"), "bad.ppp:3: start: cell (4, 0) is outside the 4x3 grid"},
      {smallWith("goal 3 2", "goal 3 3"), "bad.ppp:4: goal: cell (3, 3) is outside the 4x3 grid"},
      {smallWith("goal 3 2", "goal 0 0"), "bad.ppp:4: goal: must differ from start"},
      {smallWith("start 0 0", "start 1 0"), "bad.ppp:9: grid row 0: column 0: 'S' does not match the start line"},
      {smallWith("vbar 1 0 2", "vbar 1 5 2"), "bad.ppp:7: obstacle 1: cell (1, 5) is outside the 4x3 grid"},
      {smallWith("vbar 1 0 2", "vbar 1 0 0"), "bad.ppp:7: obstacle 1: vbar length 0 outside [1, 4]"},
      {smallWith("vbar 1 0 2", "star 1 0 2"), "bad.ppp:7: obstacle 1: expected a shape"},
      {smallWith("vbar 1 0 2", "block 1 0 2"), "bad.ppp:7: obstacle 1: expected 'block X Y WIDTH HEIGHT'"},
      {smallWith("obstacles 1", "obstacles 3"), "bad.ppp:6: obstacles: count 3 outside [0, max_obstacles = 2]"},
      {smallWith("max_obstacles 2", "max_obstacles -1"), "bad.ppp:5: max_obstacles: expected an integer in [0,"},
      {smallWith(".#..\n", "....\n"), "bad.ppp:10: grid row 1: column 1: grid shows '.' but the descriptors"},
      {smallWith(".#..\n", ".#.\n"), "bad.ppp:10: grid row 1: expected 4 cells, got 3"},
      {smallWith(".#..\n", ".#x.\n"), "bad.ppp:10: grid row 1: column 2: unknown cell 'x'"},
      {smallWith("...G\n", "...#\n"), "bad.ppp:11: grid row 2: column 3: the goal cell must be 'G'"},
      {smallWith("end\n", "end\nextra stuff\n"), "bad.ppp:14: end: trailing data after 'end'"},
      {smallWith("meta fitness turns\n", "meta fitness\n"), "bad.ppp:12: meta: expected 'meta KEY VALUE'"},
      {smallWith("meta fitness turns\n", "meta a 1\nmeta a 2\n"), "bad.ppp:13: meta: duplicate key 'a'"},
      {smallWith("end\n", ""), "bad.ppp:13: end: unexpected end of file"},
      {smallWith("grid\n", "grid\nS#..\n"), "bad.ppp:10: grid row 1: column 0: 'S' does not match the start line"},
      {std::string("ppp 1\nsize 4 3\n\x7f" "ELF\x02\x01\x01", 19), "bad.ppp:3: file: binary data (byte 0x7f at column 1)"},
      {std::string("ppp 1\0\0", 7), "bad.ppp:1: file: binary data (byte 0x00 at column 6)"},
  };
  for (const Case& c : cases) {
    const std::string message = parseError(c.text);
    EXPECT_EQ(message.rfind(c.expected, 0), 0u) << "got:      " << message << "\nexpected: " << c.expected;
  }
}

TEST(PppFileTest, BlankLinesAfterEndAreAccepted) { EXPECT_NO_THROW(parsePpp(std::string(kSmall) + "\n\n", "x")); }

TEST(PppFileTest, MissingAndDirectoryPathsAreIoErrors) {
  EXPECT_THROW(readPppFile("/nonexistent/dir/x.ppp"), IoError);
  EXPECT_THROW(readPppFile(std::filesystem::temp_directory_path().string()), IoError);
}

TEST(PppFileTest, WriterRefusesInvalidProblems) {
  Problem p = parsePpp(kSmall, "small.ppp");
  p.goal = p.start;
  EXPECT_THROW(formatPpp(p), InvalidArgument);
  p = parsePpp(kSmall, "small.ppp");
  p.metadata.emplace_back("bad key", "x");
  EXPECT_THROW(formatPpp(p), InvalidArgument);
}

}  // namespace
}  // namespace ppp
