// `ppp check` and the corpus: which seeds each PPP is played on, the verdicts, the JUnit XML, the exit statuses,
// bad input refused before anything is played or written, and one PPP per obstacle shape in a corpus.
#include "ppp_simulator/corpus_check.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ppp_core/error.hpp"
#include "ppp_core/obstacle_shape.hpp"
#include "ppp_core/problem_io.hpp"
#include "ppp_core/ppp_file.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_simulator/corpus.hpp"
#include "ppp_simulator/shrink_job.hpp"

namespace ppp {
namespace simulator {
namespace {

namespace fs = std::filesystem;

std::string tempDir() {
  char name[] = "/tmp/ppp_corpus_check_test_XXXXXX";
  const char* made = mkdtemp(name);
  EXPECT_NE(made, nullptr);
  return made;
}

/// A 6x6 PPP with a vertical bar of `length` cells at x = 2 from y = 1.
Problem barProblem(int length) {
  Problem p = Problem::empty(6, 6, 4);
  p.obstacles.push_back(Obstacle{Shape::VerticalBar, 2, 1, length, 1});
  return p;
}

/// A player that fails every run on a PPP with a bar of 3 cells, as a loop, and passes every other run; it notes
/// every seed it is asked to play.
struct FakePlayer {
  std::vector<std::uint64_t>* played;
  RunsOutcome operator()(const Problem& problem, const std::vector<std::uint64_t>& seeds) const {
    RunsOutcome outcome;
    outcome.runs = static_cast<int>(seeds.size());
    played->insert(played->end(), seeds.begin(), seeds.end());
    if (problem.obstacles.size() == 1 && problem.obstacles[0].length == 3) {
      outcome.failed = outcome.runs;
      outcome.kinds[static_cast<std::size_t>(diagnosis::kindIndex(diagnosis::kLoop))] = outcome.runs;
    }
    return outcome;
  }
};

/// A corpus of three PPPs (bars of 2, 3 and 4 cells); the bar of 3 records the seeds 11 and 12.
std::string threePppCorpus() {
  const std::string dir = tempDir();
  writePppFile(barProblem(2), dir + "/a_two.ppp");
  Problem three = barProblem(3);
  setMetadata(&three.metadata, "shrink_seeds", "11,12");
  writePppFile(three, dir + "/b_three.ppp");
  writePppFile(barProblem(4), dir + "/c_four.ppp");
  return dir;
}

CheckJob checkJob(const std::string& corpus, std::vector<std::uint64_t>* played) {
  CheckJob job;
  job.task.corpus = corpus;
  job.task.agent = "mine";
  job.play = FakePlayer{played};
  job.task.seed = 7;
  job.task.runs = 2;
  job.replay = [](const CorpusCase& c, std::uint64_t seed) {
    return "replay " + c.name + " " + std::to_string(seed);
  };
  return job;
}

TEST(CorpusCheckTest, RecordedSeedsFirstElseSeedsDerivedAsPppSimulateDerivesThem) {
  const std::string dir = threePppCorpus();
  const std::vector<CorpusCase> cases = readCorpusCases(dir, 7, 2);
  ASSERT_EQ(cases.size(), 3u);
  EXPECT_EQ(cases[0].name, "a_two");
  EXPECT_FALSE(cases[0].recorded);
  EXPECT_EQ(cases[0].seeds, (std::vector<std::uint64_t>{deriveSeed(7, {0}), deriveSeed(7, {1})}));
  EXPECT_EQ(cases[1].name, "b_three");
  EXPECT_TRUE(cases[1].recorded);
  EXPECT_EQ(cases[1].seeds, (std::vector<std::uint64_t>{11, 12}));
  EXPECT_EQ(cases[2].seeds, cases[0].seeds);
  // One file is a corpus of one.
  const std::vector<CorpusCase> one = readCorpusCases(dir + "/b_three.ppp", 7, 2);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].name, "b_three");
  EXPECT_EQ(one[0].seeds, (std::vector<std::uint64_t>{11, 12}));
  // A corpus, unlike a set, may hold PPPs of any size.
  writePppFile(Problem::empty(4, 3, 1), dir + "/d_small.ppp");
  EXPECT_EQ(readCorpusCases(dir, 7, 2).back().problem.width, 4);
  fs::remove_all(dir);
}

TEST(CorpusCheckTest, OneFailingPppOfThreeExitsOneAndTheJunitXmlNamesIt) {
  const std::string dir = threePppCorpus();
  std::vector<std::uint64_t> played;
  CheckJob job = checkJob(dir, &played);
  job.task.junit = dir + "/results/check.xml";  // its directory made
  std::ostringstream out;
  EXPECT_EQ(runCheck(job, {}, out), 1);
  const std::uint64_t s0 = deriveSeed(7, {0}), s1 = deriveSeed(7, {1});
  EXPECT_EQ(played, (std::vector<std::uint64_t>{s0, s1, 11, 12, s0, s1}));
  EXPECT_NE(out.str().find("FAIL b_three: 2 of 2 runs failed: loop (seed 11), loop (seed 12); replay: replay "
                           "b_three 11\n"),
            std::string::npos)
      << out.str();
  EXPECT_NE(out.str().find("pass a_two: 2 of 2 runs passed\n"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("mine fails 1 of 3 PPPs of " + dir + ": b_three"), std::string::npos) << out.str();

  const std::string xml = readTextFile(job.task.junit, 1 << 20);
  const std::string suite = fs::path(dir).filename().string();
  EXPECT_NE(xml.find("<testsuite name=\"" + suite + "\" tests=\"3\" failures=\"1\" errors=\"0\""), std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<testcase classname=\"ppp_check.mine\" name=\"a_two\" file=\"" + dir + "/a_two.ppp\""),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<failure type=\"loop\" message=\"mine fails b_three: 2 of 2 runs failed: loop (seed 11), "
                     "loop (seed 12)\">seed 11: loop; replay: replay b_three 11\nseed 12: loop; replay: replay "
                     "b_three 12\n</failure>"),
            std::string::npos)
      << xml;
  // Exactly one failure element, and the other two test cases close at once.
  EXPECT_EQ(xml.find("<failure"), xml.rfind("<failure"));
  EXPECT_NE(xml.find("name=\"c_four\" file=\"" + dir + "/c_four.ppp\" time=\""), std::string::npos);

  fs::remove(dir + "/b_three.ppp");  // the fault fixed (its PPP gone): every PPP passes
  std::ostringstream again;
  EXPECT_EQ(runCheck(job, {}, again), 0);
  EXPECT_NE(again.str().find("mine passes all 2 PPPs of"), std::string::npos) << again.str();
  EXPECT_NE(readTextFile(job.task.junit, 1 << 20).find("tests=\"2\" failures=\"0\""), std::string::npos);
  fs::remove_all(dir);
}

TEST(CorpusCheckTest, FailedRunsAreListedOncePerSignatureWithTheirSmallestPpp) {
  const std::string dir = threePppCorpus();
  const std::uint64_t s1 = deriveSeed(7, {1});
  CheckJob job = checkJob(dir, nullptr);
  // The bar of 3 loops on both its seeds; the bar of 4 loops the same way on its first seed and is stuck elsewhere
  // on its second; the bar of 2 passes.
  job.play = [s1](const Problem& problem, const std::vector<std::uint64_t>& seeds) {
    RunsOutcome outcome;
    outcome.runs = 1;
    const int length = problem.obstacles.at(0).length;
    if (length == 2) return outcome;
    const bool stuck = length == 4 && seeds.at(0) == s1;
    outcome.failed = 1;
    outcome.kinds[static_cast<std::size_t>(diagnosis::kindIndex(stuck ? diagnosis::kStuck : diagnosis::kLoop))] = 1;
    outcome.signatures[stuck ? "stuck/g4-7/s4-7/t1/w3e0" : "loop2/g8-15/s1/t0/w1e1"] = 1;
    return outcome;
  };
  std::ostringstream out;
  EXPECT_EQ(runCheck(job, {}, out), 1);
  EXPECT_NE(out.str().find("2 distinct failures of mine by failure signature (docs/reference/signatures.md):\n"
                           "  3 runs on 2 PPPs: loop2/g8-15/s1/t0/w1e1 (loop); smallest b_three, 3 obstacle cells; "
                           "replay: replay b_three 11\n"
                           "  1 run on 1 PPP: stuck/g4-7/s4-7/t1/w3e0 (stuck); smallest c_four, 4 obstacle cells; "
                           "replay: replay c_four " + std::to_string(s1) + "\n"
                           "mine fails 2 of 3 PPPs"),
            std::string::npos)
      << out.str();
  fs::remove_all(dir);
}

TEST(CorpusCheckTest, BadInputIsRefusedBeforeAnyRunAndNothingIsWritten) {
  const std::string dir = threePppCorpus();
  std::vector<std::uint64_t> played;
  std::ostringstream out;

  CheckJob unwritable = checkJob(dir, &played);
  unwritable.task.junit = dir + "/a_two.ppp/check.xml";  // under a file: no directory can be made there
  EXPECT_THROW(runCheck(unwritable, {}, out), IoError);

  CheckJob walled = checkJob(dir, &played);
  walled.episode.robot_radius = 2;  // no way past any bar for a robot this wide
  walled.task.junit = dir + "/check.xml";
  try {
    runCheck(walled, {}, out);
    ADD_FAILURE() << "a PPP the robot cannot play was played";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "corpus");
    EXPECT_NE(std::string(e.what()).find("a_two.ppp: the robot cannot play it: its goal is out of reach for a robot "
                                         "of radius 2"),
              std::string::npos)
        << e.what();
  }

  Problem malformed = barProblem(2);
  setMetadata(&malformed.metadata, "shrink_seeds", "11,,12");
  writePppFile(malformed, dir + "/d_bad.ppp");
  try {
    runCheck(checkJob(dir, &played), {}, out);
    ADD_FAILURE() << "a malformed seed list was read";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.field(), "meta shrink_seeds");
    EXPECT_NE(std::string(e.what()).find("d_bad.ppp:0: meta shrink_seeds: expected run seeds separated by commas"),
              std::string::npos)
        << e.what();
  }
  fs::remove(dir + "/d_bad.ppp");

  EXPECT_THROW(readCorpusCases(dir, 7, 0), InvalidArgument);  // runs out of range
  EXPECT_THROW(readCorpusCases(dir + "/missing", 7, 2), IoError);
  EXPECT_TRUE(played.empty());
  EXPECT_FALSE(fs::exists(dir + "/check.xml"));
  fs::remove_all(dir);
}

TEST(CorpusCheckTest, AStopLeavesNoJunitXml) {
  const std::string dir = threePppCorpus();
  std::vector<std::uint64_t> played;
  CheckJob job = checkJob(dir, &played);
  job.task.junit = dir + "/check.xml";
  int asked = 0;
  std::ostringstream out;
  EXPECT_EQ(runCheck(job, [&] { return ++asked > 3; }, out), 130);
  EXPECT_EQ(played.size(), 3u);
  EXPECT_FALSE(fs::exists(job.task.junit));
  fs::remove_all(dir);
}

TEST(CorpusTest, KeepsOnePppPerObstacleShape) {
  const std::string dir = tempDir() + "/corpus";  // made by the first addition
  Corpus corpus(dir);
  Problem l_shape = Problem::empty(8, 8, 4);
  l_shape.obstacles = {Obstacle{Shape::VerticalBar, 2, 2, 3, 1}, Obstacle{Shape::HorizontalBar, 3, 4, 1, 1}};
  const CorpusAddition first = corpus.add(l_shape);
  EXPECT_TRUE(first.added);
  EXPECT_EQ(fs::path(first.file).parent_path(), fs::path(dir));
  EXPECT_EQ(readPppFile(first.file).obstacles, l_shape.obstacles);
  // The same L moved and mirrored (its foot to the left), then turned on its side: the same trap, for this corpus
  // and for one read from the directory afterwards.
  Problem moved = Problem::empty(8, 8, 4);
  moved.obstacles = {Obstacle{Shape::VerticalBar, 5, 1, 3, 1}, Obstacle{Shape::HorizontalBar, 4, 3, 1, 1}};
  Problem turned = Problem::empty(8, 8, 4);
  turned.obstacles = {Obstacle{Shape::HorizontalBar, 1, 5, 3, 1}, Obstacle{Shape::HorizontalBar, 1, 6, 1, 1}};
  EXPECT_EQ(corpus.add(moved).file, first.file);
  Corpus reread(dir);
  const CorpusAddition again = reread.add(turned);
  EXPECT_FALSE(again.added);
  EXPECT_EQ(again.file, first.file);
  // A straight bar of three is another shape.
  Problem bar = Problem::empty(8, 8, 4);
  bar.obstacles = {Obstacle{Shape::VerticalBar, 2, 2, 3, 1}};
  const CorpusAddition other = reread.add(bar);
  EXPECT_TRUE(other.added);
  EXPECT_NE(other.file, first.file);
  EXPECT_EQ(readCorpusCases(dir, 1, 1).size(), 2u);
  fs::remove_all(fs::path(dir).parent_path());
}

TEST(CorpusTest, NeverOverwritesAFileOfTheNameItWouldTake) {
  const std::string dir = tempDir();
  Problem l_shape = Problem::empty(8, 8, 4);
  l_shape.obstacles = {Obstacle{Shape::VerticalBar, 2, 2, 3, 1}, Obstacle{Shape::HorizontalBar, 3, 4, 1, 1}};
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx",
                static_cast<unsigned long long>(nameHash(obstacleShape(decodeGrid(l_shape)))));
  const std::string taken = dir + "/trap_" + hash + ".yaml";  // another map under the L's name
  writeProblemFile(barProblem(2), taken);
  const CorpusAddition added = Corpus(dir).add(l_shape);
  EXPECT_TRUE(added.added);
  EXPECT_EQ(added.file, dir + "/trap_" + hash + "_2.ppp");
  EXPECT_EQ(decodeGrid(readProblemFile(taken)), decodeGrid(barProblem(2)));
  EXPECT_EQ(readCorpusCases(dir, 1, 1).size(), 2u);  // two names, both readable
  fs::remove_all(dir);
}

TEST(CorpusTest, RefusesASetOrAFileBeforeAnything) {
  const std::string dir = tempDir();
  std::ofstream(dir + "/set.csv") << "id,file\n";  // a set: its set.csv would not list what is added
  EXPECT_THROW(Corpus{dir}, IoError);
  EXPECT_THROW(Corpus{dir + "/set.csv"}, IoError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace simulator
}  // namespace ppp
