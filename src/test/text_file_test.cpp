#include "ppp_core/text_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "ppp_core/error.hpp"

namespace ppp {
namespace {

namespace fs = std::filesystem;

class TextFileTest : public ::testing::Test {
 protected:
  void TearDown() override { fs::remove(path_); }
  std::string path_ = (fs::temp_directory_path() / "text_file_test.txt").string();
};

/// `bytes` bytes of a pattern that does not repeat at the 8 MB chunk size.
std::string pattern(std::size_t bytes) {
  std::string text(bytes, ' ');
  for (std::size_t i = 0; i < bytes; ++i) text[i] = static_cast<char>('a' + (i * 7 + i / 251) % 26);
  return text;
}

TEST_F(TextFileTest, ReadsBackWhatWasWrittenAcrossChunkBoundaries) {
  constexpr std::size_t kChunk = std::size_t{8} << 20;
  for (std::size_t bytes : {std::size_t{0}, std::size_t{5}, kChunk - 1, kChunk, kChunk + 1, 2 * kChunk + 3}) {
    const std::string text = pattern(bytes);
    writeFileAtomically(path_, text);
    EXPECT_EQ(readTextFile(path_, 3 * kChunk), text) << bytes << " bytes";
  }
}

TEST_F(TextFileTest, AStopBetweenChunksInterruptsAndTheLimitIsNamed) {
  writeFileAtomically(path_, pattern((std::size_t{8} << 20) * 2 + 1));  // three chunks
  int asked = 0;
  EXPECT_THROW(readTextFile(path_, std::size_t{1} << 30, [&asked] { return ++asked == 2; }), Interrupted);
  EXPECT_EQ(asked, 2);
  asked = 0;
  EXPECT_EQ(readTextFile(path_, std::size_t{1} << 30, [&asked] { return ++asked > 3; }).size(),
            (std::size_t{8} << 20) * 2 + 1);
  EXPECT_EQ(asked, 3);  // one question per chunk read
  try {
    readTextFile(path_, 1000);
    ADD_FAILURE() << "a file over the limit was read";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("exceeds the limit of 1000 bytes"), std::string::npos) << e.what();
  }
}

TEST_F(TextFileTest, AnAtomicFileReplacesThePathOnlyWhenCommitted) {
  writeFileAtomically(path_, "old\n");
  {
    AtomicFile file(path_);
    file.write("new ");
    file.write("text\n");
    EXPECT_EQ(readTextFile(path_, 100), "old\n");  // readers see the old file until the commit
  }  // dropped without a commit: the old file stays, the temporary file goes
  EXPECT_EQ(readTextFile(path_, 100), "old\n");
  EXPECT_FALSE(fs::exists(path_ + ".tmp"));
  AtomicFile file(path_);
  file.write("new ");
  file.write("text\n");
  file.commit();
  EXPECT_EQ(readTextFile(path_, 100), "new text\n");
  EXPECT_FALSE(fs::exists(path_ + ".tmp"));
  EXPECT_THROW(file.write("more"), IoError);
}

TEST_F(TextFileTest, AnAtomicFileInAMissingDirectoryNamesThePath) {
  const std::string path = (fs::temp_directory_path() / "no_such_directory_here" / "out.csv").string();
  try {
    AtomicFile file(path);
    ADD_FAILURE() << "opened a file in a missing directory";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ppp
