#include "ppp_generator/set_csv.hpp"

#include <gtest/gtest.h>

#include "ppp_core/csv.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace generator {
namespace {

/// set.csv text: the header, then `rows` each on a line.
std::string setCsv(const std::vector<std::string>& rows) {
  std::string text = csvLine(setCsvHeader()) + "\n";
  for (const std::string& row : rows) text += row + "\n";
  return text;
}

/// The message of the ParseError parseSetCsv throws for `text` read as sets/a/set.csv.
std::string errorOf(const std::string& text) {
  try {
    parseSetCsv(text, "sets/a/set.csv");
  } catch (const ParseError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(SetCsv, ListsTheFilesInOrder) {
  EXPECT_EQ(parseSetCsv(setCsv({"ppp_001,ppp_001.ppp,turns,4", "", "ppp_000,ppp_000.ppp,turns,5"}), "set.csv"),
            (std::vector<std::string>{"ppp_001.ppp", "ppp_000.ppp"}));
}

TEST(SetCsv, ReadsSetsWrittenBeforeNearestDifference) {
  std::vector<std::string> header = setCsvHeader();
  header.pop_back();
  EXPECT_EQ(parseSetCsv(csvLine(header) + "\nppp_000,ppp_000.ppp,turns,5", "set.csv"),
            std::vector<std::string>{"ppp_000.ppp"});
}

TEST(SetCsv, ErrorsNameTheLineAndField) {
  EXPECT_EQ(errorOf(""), "sets/a/set.csv:1: header: not a PPP set file (expected the header written by ppp generate)");
  EXPECT_EQ(errorOf("id,file\nppp_000,ppp_000.ppp,turns\n").rfind("sets/a/set.csv:1: header: ", 0), 0u);
  EXPECT_EQ(errorOf(setCsv({"ppp_000,ppp_000.ppp,turns", "ppp_001"})), "sets/a/set.csv:3: file: expected id,file,...");
  EXPECT_EQ(errorOf(setCsv({})), "sets/a/set.csv:1: set: lists no PPPs");
  EXPECT_EQ(errorOf(setCsv({"", ""})), "sets/a/set.csv:3: set: lists no PPPs");
}

// The reader used to take any second field for a file and join it to the set's directory: ../outside.ppp or an
// absolute path was read from outside the set, and the same file listed twice became two PPPs.
TEST(SetCsv, RefusesFileNamesOutsideTheSetDirectory) {
  const std::vector<std::string> outside{"../outside.ppp", "/etc/passwd.ppp", "sub/ppp_000.ppp", "ppp_000.txt",
                                         ".ppp", "\"ppp_000.ppp\"", std::string("ppp\0.ppp", 8), "", "a\\b.ppp"};
  for (const std::string& name : outside) {
    EXPECT_EQ(errorOf(setCsv({"ppp_000," + name + ",turns,1"})).rfind("sets/a/set.csv:2: file: ", 0), 0u) << name;
  }
  EXPECT_NE(errorOf(setCsv({"ppp_000,ppp\x01.ppp,turns,1"})).find("'ppp\\x01.ppp' is not a .ppp file name"),
            std::string::npos);
}

TEST(SetCsv, RefusesAFileListedTwice) {
  EXPECT_NE(errorOf(setCsv({"ppp_000,ppp_000.ppp,turns,1", "ppp_001,ppp_001.ppp,turns,1", "x,ppp_000.ppp,turns,1"}))
                .find("sets/a/set.csv:4: file: 'ppp_000.ppp' is listed twice (first on line 2)"),
            std::string::npos);
}

}  // namespace
}  // namespace generator
}  // namespace ppp
