#include "ppp_simulator/results_file.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <utility>

#include "ppp_core/csv.hpp"
#include "ppp_core/error.hpp"
#include "ppp_simulator/planner_moves.hpp"

namespace ppp {
namespace simulator {
namespace {

namespace fs = std::filesystem;

agents::EpisodeResult row(int run, bool passed) {
  agents::EpisodeResult r;
  r.set = "turns";
  r.problem = "ppp_000";
  r.agent = "random";
  r.run = run;
  r.seed = 1000 + run;
  r.passed = passed;
  r.steps = 10 + run;
  r.reason = passed ? "goal_reached" : "budget_exhausted";
  if (!passed) {
    r.diagnosis = "wandering";
    r.diagnosis_step = 5;
    r.signature = "wandering/g4-7/s4-7/t1/w0e0";
  }
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
  std::vector<agents::EpisodeResult> rows;
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
  std::ofstream(path_) << "set,problem,agent,run,seed,pass,steps,bumps,path_length,optimal_length,reason,soft_failure,"
                          "diagnosis,diagnosis_step,loop_period,endless_step,signature\n"
                       << "turns,ppp_000,random,zero,1,1,1,0,1,1,goal_reached,0,,,,,\n";
  try {
    ResultsFile file(path_);
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), path_ + ":2: run: expected a whole number, got 'zero'");
  }
}

/// Expects the file at `path` holding `old_text` (an earlier version's) to be refused on opening with a message that
/// begins `path:1: header: written by an earlier PPP Lab, without ` + `missing` and says what to do, the file left as
/// it was.
void expectEarlierFileRefusedUntouched(const std::string& path, const std::string& old_text, const std::string& missing) {
  std::ofstream(path) << old_text;
  try {
    ResultsFile file(path);
    ADD_FAILURE() << "an earlier results.csv was opened";
  } catch (const ParseError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(path + ":1: header: written by an earlier PPP Lab, without " + missing, 0), 0u) << what;
    EXPECT_NE(what.find("new output directory"), std::string::npos) << what;
  }
  std::ifstream in(path);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), old_text);  // nothing appended or cut
}

TEST_F(ResultsFileTest, FilesWrittenBeforeRunsWereDiagnosedAreRefusedWithWhatToDo) {
  expectEarlierFileRefusedUntouched(path_,
                                    "set,problem,agent,run,seed,pass,steps,bumps,path_length,optimal_length,reason,"
                                    "soft_failure\nturns,ppp_000,random,0,1,0,300,0,1,1,budget_exhausted,0\n",
                                    "the diagnosis columns");
}

TEST_F(ResultsFileTest, FilesWrittenBeforeFailuresHadSignaturesAreRefusedUntouched) {
  // A resumed experiment never mixes rows with and without signatures: the older file is refused as it stands.
  expectEarlierFileRefusedUntouched(path_,
                                    "set,problem,agent,run,seed,pass,steps,bumps,path_length,optimal_length,reason,"
                                    "soft_failure,diagnosis,diagnosis_step,loop_period,endless_step\n"
                                    "turns,ppp_000,random,0,1,0,300,0,1,1,budget_exhausted,0,loop,100,2,\n",
                                    "the signature column");
}

/// Row `run` of the planner agent `mine`, with one action per step (E, E, S, ...).
agents::EpisodeResult plannerRow(int run, int steps) {
  agents::EpisodeResult r = row(run, false);
  r.agent = "mine";
  r.steps = steps;
  r.reason = "no_path";
  r.diagnosis = "missed_route";
  r.diagnosis_step = -1;
  r.signature = "missed_route/g16-31/s1/t0/w0e0";
  for (int i = 0; i < steps; ++i) r.actions.push_back(i % 3 == 2 ? Action::South : Action::East);
  return r;
}

TEST_F(ResultsFileTest, PlannerRunsKeepTheirMovesBesideTheResults) {
  const std::string moves_path = (fs::path(path_).parent_path() / kPlannerMovesFile).string();
  fs::remove(moves_path);
  {
    ResultsFile file(path_);
    file.append({row(0, true)});  // no actions: no moves file yet
    EXPECT_FALSE(fs::exists(moves_path));
    file.append({plannerRow(0, 4), row(1, true), plannerRow(1, 2)});
  }
  std::ifstream in(moves_path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "set,problem,agent,run,moves\nturns,ppp_000,mine,0,2232\nturns,ppp_000,mine,1,22\n");
  // Read back onto the rows of results.csv, which hold no actions: each planner row gets its own.
  std::vector<agents::EpisodeResult> rows = readResultsFile(path_);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_TRUE(rows[2].actions.empty());
  attachPlannerMoves(moves_path, &rows);
  EXPECT_EQ(rows[1].actions, plannerRow(0, 4).actions);
  EXPECT_TRUE(rows[2].actions.empty());
  EXPECT_EQ(rows[3].actions, plannerRow(1, 2).actions);
  fs::remove(moves_path);
}

TEST_F(ResultsFileTest, PlannerMovesOfARunPlayedAgainAndBadLinesAreHandled) {
  const std::string moves_path = (fs::temp_directory_path() / "planner_moves_test.csv").string();
  // Run 0 played twice (the last line stands), run 1's line has one action too many for its row (stale: left
  // out), and a half-written last line (the process died mid-write) is left out.
  std::ofstream(moves_path) << "set,problem,agent,run,moves\nturns,ppp_000,mine,0,11\nturns,ppp_000,mine,0,222\n"
                            << "turns,ppp_000,mine,1,333\nturns,ppp_000,mine,2,4";
  std::vector<agents::EpisodeResult> rows = {plannerRow(0, 3), plannerRow(1, 2), plannerRow(2, 1)};
  for (agents::EpisodeResult& r : rows) r.actions.clear();
  attachPlannerMoves(moves_path, &rows);
  EXPECT_EQ(rows[0].actions, std::vector<Action>(3, Action::East));
  EXPECT_TRUE(rows[1].actions.empty());
  EXPECT_TRUE(rows[2].actions.empty());
  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {"set,problem,agent,run\n", ":1: header: expected 'set,problem,agent,run,moves'"},
           {"set,problem,agent,run,moves\nturns,ppp_000,mine,0,129\n", ":2: moves: expected action digits 0 to 8, got '9'"},
           {"set,problem,agent,run,moves\nturns,ppp_000,mine,first,1\n", ":2: run: expected a run number, got 'first'"},
           {"set,problem,agent,run,moves\nturns,ppp_000,mine,0\n", ":2: moves: expected 5 fields, got 4"}}) {
    std::ofstream(moves_path) << text;
    try {
      attachPlannerMoves(moves_path, &rows);
      ADD_FAILURE() << "accepted " << text;
    } catch (const ParseError& e) {
      EXPECT_EQ(std::string(e.what()), moves_path + message);
    }
  }
  fs::remove(moves_path);
  attachPlannerMoves(moves_path, &rows);  // no file: nothing to attach, no error
}

TEST(ResultsCsvText, RowsOfTextWithErrorsNamingTheGivenPath) {
  const std::string header =
      "set,problem,agent,run,seed,pass,steps,bumps,path_length,optimal_length,reason,soft_failure,diagnosis,"
      "diagnosis_step,loop_period,endless_step,signature\n";
  const std::string good = "turns,ppp_000,random,0,1,1,1,0,1,1,goal_reached,0,,,,,\n";
  const auto rows = parseResultsCsv(header + good + "turns,ppp_000,ran", "out/results.csv");
  ASSERT_EQ(rows.size(), 1u);  // the half-written last line is left out
  EXPECT_EQ(rows[0].reason, "goal_reached");
  try {
    parseResultsCsv(header + good + "turns,ppp_000,random,zero,1,1,1,0,1,1,goal_reached,0,,,,,\n", "out/results.csv");
    ADD_FAILURE() << "run zero accepted";
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), "out/results.csv:3: run: expected a whole number, got 'zero'");
  }
}

TEST(ResultsCsvText, LengthsAreWholeNumbersOrEightDecimals) {
  // 4-connected lengths are written as the whole numbers they always were; a diagonal's sqrt(2) with eight
  // decimals, which reads back to the same text (a resume rewrites nothing).
  agents::EpisodeResult r;
  r.set = "s";
  r.problem = "p";
  r.agent = "astar";
  r.reason = "goal_reached";
  r.passed = true;
  r.path_length = 12;
  r.optimal_length = -1;
  std::string line;
  agents::appendCsvRow(r, &line);
  EXPECT_EQ(line, "s,p,astar,0,0,1,0,0,12,-1,goal_reached,0,,,,,\n");
  r.path_length = 3 + 2 * std::sqrt(2.0);
  r.optimal_length = 5.65685424949238;
  line.clear();
  agents::appendCsvRow(r, &line);
  EXPECT_EQ(line, "s,p,astar,0,0,1,0,0,5.82842712,5.65685425,goal_reached,0,,,,,\n");
  const agents::EpisodeResult back = agents::parseCsvRow(line.substr(0, line.size() - 1), "x.csv", 2);
  EXPECT_NEAR(back.path_length, 5.82842712, 1e-12);
  // A length that rounds to a whole number at eight decimals is written as that number (the text of a row read
  // back and written again does not change).
  r.path_length = 7 + 1.5e-9;
  r.optimal_length = 2.999999996;
  EXPECT_EQ(csvLine(agents::toCsvFields(r)), "s,p,astar,0,0,1,0,0,7,3,goal_reached,0,,,,,");
  EXPECT_THROW(agents::parseCsvRow("s,p,astar,0,0,1,0,0,7,-0.5,goal_reached,0,,,,,", "x.csv", 2), ParseError);  // only -1 is negative
  std::string again;
  agents::appendCsvRow(back, &again);
  EXPECT_EQ(again, line);
  for (const std::string bad : {"s,p,a,0,0,0,0,0,long,1,r,0,stuck,0,,,stuck/g1/s1/t0/w0e0/G0e0d0", "s,p,a,0,0,0,0,0,1,nan,r,0,stuck,0,,,stuck/g1/s1/t0/w0e0/G0e0d0",
                                "s,p,a,0,0,0,0,0,-2,1,r,0,stuck,0,,,stuck/g1/s1/t0/w0e0/G0e0d0"}) {
    EXPECT_THROW(agents::parseCsvRow(bad, "x.csv", 3), ParseError) << bad;
  }
  try {
    agents::parseCsvRow("s,p,a,0,0,0,0,0,1e99,1,r,0,stuck,0,,,stuck/g1/s1/t0/w0e0/G0e0d0", "x.csv", 3);
    ADD_FAILURE() << "1e99 accepted";
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), "x.csv:3: path_length: expected a length, got '1e99'");
  }
}

TEST(ResultsCsvText, DiagnosisFieldsAreCheckedAgainstTheRunAndEachOther) {
  const std::string head = "s,p,a,0,1,";
  const auto error = [&](const std::string& tail) {
    try {
      agents::parseCsvRow(head + tail, "x.csv", 4);
    } catch (const ParseError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  // Good rows: a clean pass, a detour, a loop proven endless, a planner's missed route.
  EXPECT_EQ(error("1,9,0,9,9,goal_reached,0,,,,,"), "accepted");
  EXPECT_EQ(error("1,30,0,30,9,goal_reached,1,detour,,,,detour/g4-7/s2-3/t1/w0e2"), "accepted");
  EXPECT_EQ(error("0,300,0,80,9,budget_exhausted,0,loop,56,2,58,loop2/g4-7/s8-15/t2/w1e0"), "accepted");
  EXPECT_EQ(error("0,12,0,12,9,no_path,0,missed_route,,,,missed_route/g1/s8-15/t1/w0e1/G0e2d3"), "accepted");
  EXPECT_EQ(error("0,300,0,80,9,budget_exhausted,0,spiral,56,,,"),
            "x.csv:4: diagnosis: expected one of stuck, loop, confined, wandering, detour, missed_route, no_route, "
            "reported or nothing, got 'spiral'");
  EXPECT_EQ(error("1,9,0,9,9,goal_reached,0,loop,0,2,,"),
            "x.csv:4: diagnosis: 'loop' does not fit pass 1, soft_failure 0 (a clean pass has none, a soft failure is "
            "a detour)");
  EXPECT_NE(error("0,300,0,80,9,budget_exhausted,0,,,,,").find("diagnosis: '' does not fit pass 0"), std::string::npos);
  EXPECT_NE(error("1,30,0,30,9,goal_reached,1,loop,0,2,,").find("a soft failure is a detour"), std::string::npos);
  EXPECT_EQ(error("0,300,0,80,9,budget_exhausted,0,loop,56,,,"),
            "x.csv:4: loop_period: a loop has a period of at least 2, and only a loop has one");
  EXPECT_EQ(error("0,300,0,80,9,budget_exhausted,0,stuck,56,2,,"),
            "x.csv:4: loop_period: a loop has a period of at least 2, and only a loop has one");
  EXPECT_EQ(error("0,300,0,80,9,budget_exhausted,0,confined,56,,60,"), "x.csv:4: endless_step: only a loop is endless");
  EXPECT_EQ(error("0,300,0,80,9,budget_exhausted,0,stuck,-1,,,"),
            "x.csv:4: diagnosis_step: expected a whole number of at least 0, got '-1'");
  EXPECT_EQ(error("0,300,0,80,9,budget_exhausted,0,stuck,301,,,"),
            "x.csv:4: diagnosis_step: a step after the run's last (300)");
  // The signature: of a failed or soft-failed run only, well formed, and beginning with what the diagnosis and the
  // reason say.
  EXPECT_EQ(error("0,12,0,12,9,no_path,0,missed_route,,,,"),
            "x.csv:4: signature: a failed or soft-failed run has a signature, a clean pass none");
  EXPECT_EQ(error("1,9,0,9,9,goal_reached,0,,,,,detour/g4-7/s2-3/t1/w0e2"),
            "x.csv:4: signature: a failed or soft-failed run has a signature, a clean pass none");
  EXPECT_EQ(error("0,300,0,80,9,budget_exhausted,0,loop,56,2,58,loop3-4/g4-7/s8-15/t2/w1e0"),
            "x.csv:4: signature: 'loop3-4/g4-7/s8-15/t2/w1e0' does not begin with 'loop2/', as its diagnosis and reason "
            "say");
  EXPECT_EQ(error("0,12,0,12,9,collision,0,reported,,,,no_path/g16-31/s1/t0/w0e0"),
            "x.csv:4: signature: 'no_path/g16-31/s1/t0/w0e0' does not begin with 'collision/', as its diagnosis and reason "
            "say");
  EXPECT_EQ(error("0,300,0,80,9,budget_exhausted,0,stuck,56,,,stuck/g4-7/s8-15"),
            "x.csv:4: signature: expected HOW/gG/sS/tT/wOeE[/GOeEdD], got 'stuck/g4-7/s8-15'");
  EXPECT_EQ(error("0,300,0,80,9,budget_exhausted,0,stuck,56,,,stuck/g4-7/s8-15/t1/w3e2"),
            "x.csv:4: signature: a bad site shape 'w3e2'");
}

TEST_F(ResultsFileTest, RewriteKeepsTheGivenOrder) {
  ResultsFile file(path_);
  file.append({row(1, true), row(0, true)});
  file.rewrite({row(0, true), row(1, true)});
  const auto rows = readResultsFile(path_);
  EXPECT_EQ(rows[0].run, 0);
  EXPECT_EQ(rows[1].run, 1);
}

TEST_F(ResultsFileTest, ARewriteLargerThanItsBlocksIsWholeAndInOrder) {
  // About 6 MB of rows: the rewrite writes several blocks of 4 MB, and appending goes on after it.
  std::vector<agents::EpisodeResult> rows;
  for (int run = 0; run < 80000; ++run) rows.push_back(row(run, run % 3 == 0));
  ResultsFile file(path_);
  file.append({row(7, false)});
  file.rewrite(rows);
  file.append({row(80000, true)});
  rows.push_back(row(80000, true));
  std::string expected = csvLine(agents::resultCsvHeader()) + '\n';
  for (const agents::EpisodeResult& r : rows) agents::appendCsvRow(r, &expected);
  ASSERT_GT(expected.size(), std::size_t{4} << 20);
  std::ifstream in(path_, std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), expected);
  EXPECT_FALSE(fs::exists(path_ + ".tmp"));
}

agents::EpisodeResult lost(int run, const char* why) {
  agents::EpisodeResult r = row(run, false);
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
  const std::vector<agents::EpisodeResult> standing = standingRows(readResultsFile(path_));
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
  const std::vector<agents::EpisodeResult> rows = {row(0, true), row(0, false), lost(1, "budget_exhausted")};
  EXPECT_EQ(standingRows(rows).size(), 3u);
  EXPECT_FALSE(isLostRun(rows[2]));
  EXPECT_TRUE(isLostRun(lost(1, "timeout")));
  EXPECT_FALSE(isLostRun(lost(1, "planner_timeout")));  // a planner's own failure is a verdict on the planner
  EXPECT_TRUE(isLostReason("agent_lost"));
  EXPECT_FALSE(isLostReason("planner_lost"));
  EXPECT_TRUE(leavesAgentUnreachable("planner_lost"));
  EXPECT_TRUE(leavesAgentUnreachable("timeout"));
  EXPECT_FALSE(leavesAgentUnreachable("planner_timeout"));
}

/// The runs of the rows in results.csv, in file order.
std::vector<int> runsInFile(const std::string& path) {
  std::vector<int> runs;
  for (const agents::EpisodeResult& r : readResultsFile(path)) runs.push_back(r.run);
  return runs;
}

TEST_F(ResultsFileTest, OrderedAppenderWritesBlocksInNumberOrder) {
  ResultsFile file(path_);
  OrderedAppender appender(&file);
  appender.add(2, {row(4, true), row(5, true)});  // block 2 finishes first: it waits for 0 and 1
  EXPECT_EQ(runsInFile(path_), std::vector<int>{});
  appender.add(0, {row(0, true), row(1, false)});  // block 0 is written; 2 still waits for 1
  EXPECT_EQ(runsInFile(path_), (std::vector<int>{0, 1}));
  appender.add(1, {row(2, true), row(3, true)});  // 1, then the waiting 2
  EXPECT_EQ(runsInFile(path_), (std::vector<int>{0, 1, 2, 3, 4, 5}));
  appender.add(5, {row(10, true)});  // 3 and 4 are never finished (the work stopped): flush keeps 5 and 6
  appender.add(6, {row(12, true)});
  EXPECT_EQ(runsInFile(path_), (std::vector<int>{0, 1, 2, 3, 4, 5}));
  appender.flush();
  EXPECT_EQ(runsInFile(path_), (std::vector<int>{0, 1, 2, 3, 4, 5, 10, 12}));
}

TEST(ResultsCsvText, RowsWrittenAndParsedInOnePassMatchTheFieldByFieldWay) {
  // Names with the characters CSV quotes, and the extremes of every number.
  std::vector<agents::EpisodeResult> rows;
  for (const char* name : {"turns", "a,b", "say \"hi\"", "line\rbreak", "", "explorer_memory_5x5"}) {
    agents::EpisodeResult r;
    r.set = name;
    r.problem = std::string("p_") + name;
    r.agent = name;
    r.run = rows.size() % 2 == 0 ? 2147483647 : 0;
    r.seed = rows.size() % 2 == 0 ? 18446744073709551615ULL : 0;
    r.passed = rows.size() % 2 == 0;
    r.steps = 300;
    r.bumps = -1;
    r.path_length = 12;
    r.optimal_length = 38;
    r.reason = name;
    if (!r.passed) {  // a loop proven endless, with every diagnosis field at its extreme
      r.diagnosis = "loop";
      r.diagnosis_step = 0;
      r.loop_period = 2147483647;
      r.endless_step = 300;
      r.signature = "loop17+/gx/sx/t4/w2e2";
    }
    rows.push_back(r);
  }
  for (const agents::EpisodeResult& r : rows) {
    std::string line;
    agents::appendCsvRow(r, &line);
    EXPECT_EQ(line, csvLine(agents::toCsvFields(r)) + "\n");
    const std::string content = line.substr(0, line.size() - 1);
    const agents::EpisodeResult back = agents::parseCsvRow(content, "x.csv", 2);
    EXPECT_EQ(agents::toCsvFields(back), agents::toCsvFields(r));
    EXPECT_EQ(agents::toCsvFields(back), agents::toCsvFields(agents::fromCsvFields(agents::splitCsvLine(content, "x.csv", 2), "x.csv", 2)));
  }
  // The same errors as the field-by-field parse, quoted or not.
  for (const std::string bad : {"turns,p,a,1,2,1,3,4,5", "turns,p,a,1,2,1,3,4,5,6,r,extra", "turns,p,a,1,2,yes,3,4,5,6,r",
                                "\"turns\",p,a,x,2,1,3,4,5,6,r", "turns,p,a,1,-2,1,3,4,5,6,r", "t,p,a,1,2,1,3,4,5,6,\"r"}) {
    std::string fast, slow;
    try {
      agents::parseCsvRow(bad, "x.csv", 7);
    } catch (const ParseError& e) {
      fast = e.what();
    }
    try {
      agents::fromCsvFields(agents::splitCsvLine(bad, "x.csv", 7), "x.csv", 7);
    } catch (const ParseError& e) {
      slow = e.what();
    }
    EXPECT_FALSE(fast.empty()) << bad;
    EXPECT_EQ(fast, slow) << bad;
  }
}

}  // namespace
}  // namespace simulator
}  // namespace ppp
