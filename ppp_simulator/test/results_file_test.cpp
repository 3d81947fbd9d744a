#include "ppp_simulator/results_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "ppp_core/error.hpp"

namespace ppp {
namespace simulator {
namespace {

namespace fs = std::filesystem;

EpisodeResult row(int run, bool passed) {
  EpisodeResult r;
  r.set = "turns";
  r.problem = "ppp_000";
  r.agent = "random";
  r.run = run;
  r.seed = 1000 + run;
  r.passed = passed;
  r.steps = 10 + run;
  r.reason = passed ? "goal_reached" : "budget_exhausted";
  return r;
}

class ResultsFileTest : public ::testing::Test {
 protected:
  void TearDown() override { fs::remove(path_); }
  std::string path_ = (fs::temp_directory_path() / "results_file_test.csv").string();
};

TEST_F(ResultsFileTest, AppendsAndResumes) {
  {
    ResultsFile file(path_);
    EXPECT_TRUE(file.existing().empty());
    file.append({row(0, true), row(1, false)});
  }
  ResultsFile again(path_);
  ASSERT_EQ(again.existing().size(), 2u);
  EXPECT_EQ(again.existing()[1].steps, 11);
  EXPECT_EQ(again.done().count(RunKey{"turns", "ppp_000", "random", 1}), 1u);
  again.append({row(2, true)});
  EXPECT_EQ(readResultsFile(path_).size(), 3u);
}

TEST_F(ResultsFileTest, AHalfWrittenLastLineIsCutOff) {
  { ResultsFile(path_).append({row(0, true), row(1, true)}); }
  std::ofstream(path_, std::ios::app) << "turns,ppp_000,random,2,10";  // the process died mid-write
  ResultsFile file(path_);
  EXPECT_EQ(file.existing().size(), 2u);
  file.append({row(2, false)});
  const auto rows = readResultsFile(path_);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[2].run, 2);
  EXPECT_FALSE(rows[2].passed);
}

TEST_F(ResultsFileTest, AStopWhileReadingLeavesTheFileAsItWas) {
  std::vector<EpisodeResult> rows;
  for (int run = 0; run < 40000; ++run) rows.push_back(row(run, run % 3 == 0));
  { ResultsFile(path_).append(rows); }
  std::ofstream(path_, std::ios::app) << "turns,ppp_000,random,40000,10";  // a half-written tail
  const auto before = fs::file_size(path_);
  int asked = 0;
  // Stops at the second question: the parse asks every 16384 lines, so mid-file.
  EXPECT_THROW(ResultsFile(path_, [&asked] { return ++asked == 2; }), Interrupted);
  EXPECT_EQ(asked, 2);
  EXPECT_EQ(fs::file_size(path_), before);  // the tail is cut only by a reading that completes
  // A stop asked after the rows are parsed, while the runs are tallied, also leaves the file alone.
  asked = 0;
  EXPECT_THROW(ResultsFile(path_, [&asked] { return ++asked == 4; }), Interrupted);
  EXPECT_EQ(fs::file_size(path_), before);
  ResultsFile file(path_, [] { return false; });
  EXPECT_EQ(file.done().size(), 40000u);
}

TEST_F(ResultsFileTest, ForeignFilesAreRefused) {
  std::ofstream(path_) << "a,b,c\n1,2,3\n";
  EXPECT_THROW(ResultsFile{path_}, ParseError);
  std::ofstream(path_) << "set,problem,agent,run,seed,pass,steps,bumps,path_length,optimal_length,reason\n"
                       << "turns,ppp_000,random,zero,1,1,1,0,1,1,goal_reached\n";
  try {
    ResultsFile file(path_);
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), path_ + ":2: run: expected a whole number, got 'zero'");
  }
}

TEST(ResultsCsvText, RowsOfTextWithErrorsNamingTheGivenPath) {
  const std::string header = "set,problem,agent,run,seed,pass,steps,bumps,path_length,optimal_length,reason\n";
  const std::string good = "turns,ppp_000,random,0,1,1,1,0,1,1,goal_reached\n";
  const auto rows = parseResultsCsv(header + good + "turns,ppp_000,ran", "out/results.csv");
  ASSERT_EQ(rows.size(), 1u);  // the half-written last line is left out
  EXPECT_EQ(rows[0].reason, "goal_reached");
  try {
    parseResultsCsv(header + good + "turns,ppp_000,random,zero,1,1,1,0,1,1,goal_reached\n", "out/results.csv");
    ADD_FAILURE() << "run zero accepted";
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), "out/results.csv:3: run: expected a whole number, got 'zero'");
  }
}

TEST_F(ResultsFileTest, RewriteKeepsTheGivenOrder) {
  ResultsFile file(path_);
  file.append({row(1, true), row(0, true)});
  file.rewrite({row(0, true), row(1, true)});
  const auto rows = readResultsFile(path_);
  EXPECT_EQ(rows[0].run, 0);
  EXPECT_EQ(rows[1].run, 1);
}

EpisodeResult lost(int run, const char* why) {
  EpisodeResult r = row(run, false);
  r.reason = why;
  return r;
}

TEST_F(ResultsFileTest, LostRunsAreNotDoneAndTheirReplaySupersedesThem) {
  { ResultsFile(path_).append({row(0, true), lost(1, "timeout"), lost(2, "agent_lost"), row(3, false)}); }
  {
    ResultsFile file(path_);
    EXPECT_EQ(file.done().size(), 2u);
    EXPECT_EQ(file.done().count(RunKey{"turns", "ppp_000", "random", 1}), 0u);
    EXPECT_EQ(file.done().count(RunKey{"turns", "ppp_000", "random", 2}), 0u);
    EXPECT_EQ(file.done().count(RunKey{"turns", "ppp_000", "random", 3}), 1u);  // budget_exhausted is a verdict
    EXPECT_EQ(file.lostRuns(), 2u);
    file.append({row(2, true), lost(1, "agent_lost")});  // run 1 is lost again, run 2 now plays out
  }
  ResultsFile file(path_);
  EXPECT_EQ(file.lostRuns(), 1u);
  EXPECT_EQ(file.done().count(RunKey{"turns", "ppp_000", "random", 2}), 1u);
  const std::vector<EpisodeResult> standing = standingRows(readResultsFile(path_));
  ASSERT_EQ(standing.size(), 4u);
  EXPECT_EQ(standing[0].run, 0);
  EXPECT_EQ(standing[1].run, 3);
  EXPECT_EQ(standing[2].run, 2);
  EXPECT_TRUE(standing[2].passed);
  EXPECT_EQ(standing[3].run, 1);
  EXPECT_EQ(standing[3].reason, "agent_lost");
}

TEST_F(ResultsFileTest, RowsWithoutLostRunsAllStand) {
  // Without lost runs nothing is played twice: even rows of one run (which a resume never writes) are kept.
  const std::vector<EpisodeResult> rows = {row(0, true), row(0, false), lost(1, "budget_exhausted")};
  EXPECT_EQ(standingRows(rows).size(), 3u);
  EXPECT_FALSE(isLostRun(rows[2]));
  EXPECT_TRUE(isLostRun(lost(1, "timeout")));
  EXPECT_FALSE(isLostRun(lost(1, "planner_timeout")));  // a planner's own failure is a verdict on the planner
}

}  // namespace
}  // namespace simulator
}  // namespace ppp
