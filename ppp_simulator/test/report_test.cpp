#include "ppp_simulator/report/report.hpp"

#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/gif_animation.hpp"
#include "ppp_core/picture.hpp"
#include "ppp_core/trajectory_picture.hpp"
#include "ppp_core/ppp_file.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_generator/tree_html.hpp"

namespace ppp::simulator {
namespace {

namespace fs = std::filesystem;

/// A fresh directory under the system temp directory, removed at the end of the test.
class ReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = (fs::temp_directory_path() / ("report_test_" + std::to_string(::getpid()) + "_" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name()))
               .string();
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string read(const std::string& relative) const { return readTextFile(dir_ + "/" + relative, 16 << 20); }

  std::string dir_;
};

/// `passes` of 4 runs of `agent` on one PPP.
void addRuns(std::vector<agents::EpisodeResult>* results, const std::string& set, const std::string& problem,
             const std::string& agent, int passes) {
  for (int run = 0; run < 4; ++run) {
    agents::EpisodeResult r;
    r.set = set;
    r.problem = problem;
    r.agent = agent;
    r.run = run;
    r.seed = 1000 + static_cast<std::uint64_t>(run);
    r.passed = run < passes;
    r.steps = r.passed ? 10 : 300;
    r.reason = r.passed ? reason::kGoalReached : reason::kBudgetExhausted;
    results->push_back(r);
  }
}

/// A 5×5 PPP with a wall at x = 2 from the top (rows 0–3), start top-left, goal bottom-right.
Problem walledProblem() {
  Problem problem = Problem::empty(5, 5, 4);
  problem.obstacles.push_back(Obstacle{Shape::VerticalBar, 2, 0, 4, 1});
  return problem;
}

// 2 sets × 2 PPPs × 3 agents, 4 runs each. Mean pass rates over the PPPs, by hand:
//   alpha: astar (4 + 4)/8 → 100.00%, explorer (3/4 + 2/4)/2 → 62.50%, random (1/4 + 0)/2 → 12.50%
//   beta:  astar 100.00%,             explorer (2/4 + 1/4)/2 → 37.50%, random 0.00%
ReportInput handMadeInput() {
  std::vector<agents::EpisodeResult> results;
  addRuns(&results, "alpha", "p1", "astar", 4);
  addRuns(&results, "alpha", "p2", "astar", 4);
  addRuns(&results, "alpha", "p1", "explorer", 3);
  addRuns(&results, "alpha", "p2", "explorer", 2);
  addRuns(&results, "alpha", "p1", "random", 1);
  addRuns(&results, "alpha", "p2", "random", 0);
  addRuns(&results, "beta", "q1", "astar", 4);
  addRuns(&results, "beta", "q2", "astar", 4);
  addRuns(&results, "beta", "q1", "explorer", 2);
  addRuns(&results, "beta", "q2", "explorer", 1);
  addRuns(&results, "beta", "q1", "random", 0);
  addRuns(&results, "beta", "q2", "random", 0);

  ReportInput input;
  input.title = "Faults <&> of agents";
  input.config_text = "# experiment\nruns: 4\nseed: 7\nnote: \"<script>alert(1)</script>\"\n";
  input.control = "astar";
  input.rates = computePassRates(results, {"alpha", "beta"}, {"astar", "explorer", "random"});
  input.comparisons = {{"alpha", "beta"}};
  FailureExample failure;
  failure.set = "beta";
  failure.problem = "q1";
  failure.agent = "random";
  failure.run = 3;
  failure.seed = 12345;
  failure.ppp = walledProblem();
  failure.path = {{0, 0}, {1, 0}, {1, 1}, {1, 2}, {1, 3}, {1, 4}, {2, 4}};
  failure.reason = reason::kBudgetExhausted;
  input.failures.push_back(failure);
  return input;
}

TEST_F(ReportTest, ReferenceRatesStandBesideTheMeasuredOnes) {
  writeReport(dir_, handMadeInput());
  EXPECT_EQ(read("report.md").find("## Reference"), std::string::npos);  // none given, no section
  ReportInput input = handMadeInput();
  input.references = compareWithReference(input.rates, {{"alpha", "explorer", 85}, {"beta", "random", 10}});
  writeReport(dir_, input);
  const std::string md = read("report.md");
  // alpha/explorer: per-PPP 3/4 and 2/4, mean 0.625, sample sd 0.176777, half-width 1.959964 x 0.176777 / sqrt 2
  // = 0.245: 38.00 % to 87.00 %, and 85 % is in it. beta/random passed nothing: no spread, 10 % is out.
  EXPECT_NE(md.find("| `alpha` | `explorer` | 62.50% | 85.00% | -22.50 | 38.00% \xE2\x80\x93 87.00% | yes |"),
            std::string::npos) << md;
  EXPECT_NE(md.find("| `beta` | `random` | 0.00% | 10.00% | -10.00 | 0.00% \xE2\x80\x93 0.00% | **no** |"),
            std::string::npos) << md;
  EXPECT_LT(md.find("## Reference"), md.find("## Mann"));  // right after the pass rates
  EXPECT_NE(read("report.html").find("<h2>Reference</h2>"), std::string::npos);
}

TEST_F(ReportTest, WritesEveryFile) {
  writeReport(dir_, handMadeInput());
  for (const char* file : {"report.md", "report.html", "plots/pass_rate_by_agent.svg",
                           "plots/pass_rate_by_ppp_alpha.svg", "plots/pass_rate_by_ppp_beta.svg",
                           "pictures/beta_q1_random.png", "ppps/beta_q1.ppp"}) {
    EXPECT_TRUE(fs::is_regular_file(dir_ + "/" + file)) << file;
  }
  for (const auto& entry : fs::recursive_directory_iterator(dir_)) {
    EXPECT_NE(entry.path().extension(), ".tmp") << entry.path();
  }
  EXPECT_EQ(readPppFile(dir_ + "/ppps/beta_q1.ppp"), walledProblem());
}

TEST_F(ReportTest, MarkdownHasTheHandComputedPercentagesAndSectionsInOrder) {
  writeReport(dir_, handMadeInput());
  const std::string md = read("report.md");
  EXPECT_NE(md.find("| Agent | `alpha` | `beta` |\n|:---|---:|---:|\n"), std::string::npos) << md;
  EXPECT_NE(md.find("| `astar` | 100.00% | 100.00% |\n"), std::string::npos) << md;
  EXPECT_NE(md.find("| `explorer` | 62.50% | 37.50% |\n"), std::string::npos) << md;
  EXPECT_NE(md.find("| `random` | 12.50% | 0.00% |\n"), std::string::npos) << md;
  EXPECT_NE(md.find("| *PPPs* | 2 | 2 |\n"), std::string::npos) << md;
  EXPECT_NE(md.find("| *runs per PPP and agent* | 4 | 4 |\n"), std::string::npos) << md;
  EXPECT_NE(md.find("| *runs in total* | 24 | 24 |\n"), std::string::npos) << md;

  // Mann–Whitney, explorer: A = {0.75, 0.5}, B = {0.5, 0.25}: ranks 0.25→1, 0.5→2.5 (twice), 0.75→4;
  // R_A = 6.5, U_A = 6.5 − 3 = 3.5, U_B = 0.5, U = 0.5; σ² = 4/12·(5 − 6/12) = 1.5, z = 1.5/√1.5 = 1.225,
  // p = erfc(1.2247/√2) = 0.2207.
  EXPECT_NE(md.find("| `explorer` | 62.50% | 37.50% | 2 | 2 | 0.5 | 1.225 | 0.2207 | no |\n"), std::string::npos)
      << md;
  // astar: all four rates 1 → σ = 0, z = 0, p = 1.
  EXPECT_NE(md.find("| `astar` | 100.00% | 100.00% | 2 | 2 | 2 | 0.000 | 1.0000 | no |\n"), std::string::npos) << md;

  EXPECT_NE(md.find("](plots/pass_rate_by_agent.svg)"), std::string::npos);
  EXPECT_NE(md.find("](plots/pass_rate_by_ppp_alpha.svg)"), std::string::npos);
  EXPECT_NE(md.find("](plots/pass_rate_by_ppp_beta.svg)"), std::string::npos);
  EXPECT_NE(md.find("](pictures/beta_q1_random.png)"), std::string::npos);
  EXPECT_NE(md.find("`ppp replay ppps/beta_q1.ppp --agent random --seed 12345 -o path.png`"), std::string::npos);
  EXPECT_NE(md.find("run 3, seed `12345`"), std::string::npos);
  EXPECT_NE(md.find("```yaml\n# experiment\nruns: 4\nseed: 7\nnote: \"<script>alert(1)</script>\"\n```\n"),
            std::string::npos);  // verbatim in a fence

  const std::size_t title = md.find("# Faults \\<\\&\\> of agents\n");
  const std::size_t rates = md.find("## Pass rates");
  const std::size_t tests = md.find("## Mann");
  const std::size_t plots = md.find("## Plots");
  const std::size_t hardest = md.find("## Hardest PPPs");
  const std::size_t config = md.find("## Configuration");
  EXPECT_EQ(title, 0u);
  EXPECT_LT(title, rates);
  EXPECT_LT(rates, tests);
  EXPECT_LT(tests, plots);
  EXPECT_LT(plots, hardest);
  EXPECT_LT(hardest, config);
  EXPECT_NE(config, std::string::npos);
}

TEST_F(ReportTest, FaultsFoundCountsFailedPppsShowsTheWorstAndTheArchive) {
  // Failed = passed in under half the runs: explorer fails q2 (1/4) but not p2 or q1 (2/4, exactly half);
  // random passes at most 1/4 anywhere, so it fails 2 of 2 on both sets.
  ReportInput input = handMadeInput();
  FailureExample worst = input.failures[0];
  worst.agent = "explorer";
  worst.problem = "q2";
  input.worst = {worst};
  input.sets = {{"alpha", 0.75, ""}, {"beta", 1.25, "<svg><title>the beta archive</title></svg>\n"}};
  writeReport(dir_, input);
  const std::string md = read("report.md");
  const std::size_t faults = md.find("## Faults found");
  ASSERT_NE(faults, std::string::npos) << md;
  EXPECT_LT(md.find("## Mann"), faults);
  EXPECT_LT(faults, md.find("## Plots"));
  const std::string section = md.substr(faults, md.find("## Plots") - faults);
  EXPECT_NE(section.find("| `astar` | 0 of 2 | 0 of 2 |\n"), std::string::npos) << section;
  EXPECT_NE(section.find("| `explorer` | 0 of 2 | 1 of 2 |\n"), std::string::npos) << section;
  EXPECT_NE(section.find("| `random` | 2 of 2 | 2 of 2 |\n"), std::string::npos) << section;
  EXPECT_NE(section.find("### `beta` / `q2` \xE2\x80\x94 `explorer`"), std::string::npos) << section;
  EXPECT_NE(section.find("](pictures/beta_q2_explorer.png)"), std::string::npos) << section;
  EXPECT_NE(section.find("### Archive of `beta`"), std::string::npos) << section;
  EXPECT_EQ(section.find("### Archive of `alpha`"), std::string::npos) << section;
  EXPECT_NE(md.find("| *diversity* | 0.750 | 1.250 |\n"), std::string::npos) << md;
  EXPECT_TRUE(fs::is_regular_file(dir_ + "/pictures/beta_q2_explorer.png"));
  EXPECT_NE(read("report.html").find("<svg><title>the beta archive</title></svg>"), std::string::npos);
}

TEST_F(ReportTest, DistinctFailuresListEachAgentsKindsWithTheirSmallestPppAndReplay) {
  ReportInput input = handMadeInput();
  const Problem q2 = walledProblem();
  AgentFailureKinds explorer{"explorer", 3, 9, {}};
  explorer.shown.push_back(FailureKind{DistinctFailure{"loop2/g1/s4-7/t1/w2e0/G1e0d1", 6, 2, 0, 4}, "loop", "beta", "q2",
                                       q2, 5, "--agent explorer"});
  explorer.shown.push_back(FailureKind{DistinctFailure{"stuck/g4-7/s2-3/t0/w3e0", 2, 1, 0, 4}, "stuck", "beta", "q2",
                                       q2, 8, "--agent explorer"});
  AgentFailureKinds planner{"mine", 1, 1, {}};
  planner.shown.push_back(FailureKind{DistinctFailure{"missed_route/g8-15/s0/t0/w1e1", 1, 1, 0, 4}, "missed_route",
                                      "alpha", "p1", q2, 7, ""});
  input.failure_kinds = {explorer, planner};
  writeReport(dir_, input);
  const std::string md = read("report.md");
  const std::size_t at = md.find("### Distinct failures");
  ASSERT_NE(at, std::string::npos) << md;
  EXPECT_GT(at, md.find("## Faults found"));
  EXPECT_LT(at, md.find("## Plots"));
  EXPECT_NE(md.find("`explorer`: 3 distinct failures in 9 failed runs (the 1 least common not listed)\n\n"
                    "| Signature | Diagnosis | Runs | PPPs | Smallest PPP | Replay |\n"),
            std::string::npos)
      << md;
  // One file per PPP, however many kinds it is the smallest of; a planner's run is played again by its shrink.
  EXPECT_NE(md.find("| `loop2/g1/s4-7/t1/w2e0/G1e0d1` | loop | 6 | 2 | `beta/q2 (4 obstacle cells)` | "
                    "`ppp replay ppps/failures/beta_q2.ppp --agent explorer --seed 5 -o path.png` |\n"
                    "| `stuck/g4-7/s2-3/t0/w3e0` | stuck | 2 | 1 | `beta/q2 (4 obstacle cells)` | "
                    "`ppp replay ppps/failures/beta_q2.ppp --agent explorer --seed 8 -o path.png` |\n"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("`mine`: 1 distinct failure in 1 failed run\n"), std::string::npos) << md;
  EXPECT_NE(md.find("`roslaunch launch/shrink.launch input:=ppps/failures/alpha_p1.ppp agent:=mine output:=check.ppp "
                    "config:=EXPERIMENT.yaml args:=\"--seed 7\"`"),
            std::string::npos)
      << md;
  EXPECT_EQ(read("ppps/failures/beta_q2.ppp"), formatPpp(q2));
  EXPECT_TRUE(fs::is_regular_file(dir_ + "/ppps/failures/alpha_p1.ppp"));
  EXPECT_NE(read("report.html").find("<td><code>stuck/g4-7/s2-3/t0/w3e0</code></td><td>stuck</td>"), std::string::npos);
  input.failure_kinds.clear();  // no agent fails: no section
  writeReport(dir_, input);
  EXPECT_EQ(read("report.md").find("### Distinct failures"), std::string::npos);
}

TEST_F(ReportTest, DiagnosesAreTabledPerAgentAndSetAndSaidBesideEachPicture) {
  // handMadeInput()'s runs, their failures diagnosed by hand: explorer wandering everywhere (3 failed runs on
  // alpha, 5 on beta); random looping on alpha (7, of which run 3 on each PPP endless: 2) and confined on beta (8).
  ReportInput input = handMadeInput();
  std::vector<agents::EpisodeResult> results;
  for (const auto& [set, problems] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"alpha", {"p1", "p2"}}, {"beta", {"q1", "q2"}}}) {
    const std::map<std::string, std::vector<int>> passes = {
        {"alpha", {4, 4, 3, 2, 1, 0}}, {"beta", {4, 4, 2, 1, 0, 0}}};
    int k = 0;
    for (const std::string agent : {"astar", "explorer", "random"}) {
      for (const std::string& problem : problems) addRuns(&results, set, problem, agent, passes.at(set)[k++]);
    }
  }
  for (agents::EpisodeResult& r : results) {
    if (r.passed) continue;
    r.diagnosis = r.agent == "explorer" ? diagnosis::kWandering : r.set == "alpha" ? diagnosis::kLoop : diagnosis::kConfined;
    r.diagnosis_step = 100;
    if (r.diagnosis == diagnosis::kLoop) r.loop_period = 2;
    if (r.diagnosis == diagnosis::kLoop && r.run == 3) r.endless_step = 102;
  }
  input.rates = computePassRates(results, {"alpha", "beta"}, {"astar", "explorer", "random"});
  input.failures[0].diagnosis.kind = diagnosis::kLoop;
  input.failures[0].diagnosis.step = 1;
  input.failures[0].diagnosis.period = 2;
  input.failures[0].cycle = {{1, 0}, {1, 1}};
  writeReport(dir_, input);
  const std::string md = read("report.md");
  const std::size_t start = md.find("## Diagnoses"), end = md.find("## Faults found");
  ASSERT_LT(start, end) << md;
  const std::string section = md.substr(start, end - start);
  EXPECT_NE(section.find("| Agent | Set | loop | confined | wandering |\n"), std::string::npos) << section;
  EXPECT_NE(section.find("| `explorer` | `alpha` | \xE2\x80\x94 | \xE2\x80\x94 | 3 |\n"), std::string::npos) << section;
  EXPECT_NE(section.find("| `random` | `alpha` | 7 (2 endless) | \xE2\x80\x94 | \xE2\x80\x94 |\n"), std::string::npos) << section;
  EXPECT_NE(section.find("| `explorer` | `beta` | \xE2\x80\x94 | \xE2\x80\x94 | 5 |\n"), std::string::npos) << section;
  EXPECT_NE(section.find("| `random` | `beta` | \xE2\x80\x94 | 8 | \xE2\x80\x94 |\n"), std::string::npos) << section;
  EXPECT_EQ(section.find("`astar`"), std::string::npos) << section;  // it never failed
  EXPECT_NE(md.find("- diagnosis loop: from step 1 the robot repeats a cycle of 2 actions over 2 cells to the end, "
                    "sensing nothing new (the cycle's cells are pink)\n"),
            std::string::npos)
      << md;
  EXPECT_NE(read("report.html").find("<li>diagnosis loop: from step 1"), std::string::npos);
}

TEST_F(ReportTest, AShrunkWorstPppIsShownBesideItWithItsFileAndReplayCommand) {
  ReportInput input = handMadeInput();
  FailureExample worst = input.failures[0];
  ShrunkExample shrunk;
  shrunk.ppp = Problem::empty(5, 5, 4);
  shrunk.ppp.obstacles.push_back(Obstacle{Shape::VerticalBar, 2, 1, 1, 1});
  shrunk.path = {{0, 0}, {1, 0}, {1, 1}};
  shrunk.cycle = {{1, 0}, {1, 1}};
  shrunk.summary = "1 of 1 descriptors, 1 of 4 obstacle cells, still loop in 1 of 1 run";
  worst.problem = "q2";
  worst.shrunk = shrunk;
  input.worst = {worst};
  writeReport(dir_, input);
  const std::string md = read("report.md");
  EXPECT_NE(md.find("- shrunk: 1 of 1 descriptors, 1 of 4 obstacle cells, still loop in 1 of 1 run "
                    "(`ppps/beta_q2_random_shrunk.ppp`; replay: `ppp replay ppps/beta_q2_random_shrunk.ppp --agent "
                    "random --seed 12345 -o path.png`)"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("](pictures/beta_q2_random_shrunk.png)"), std::string::npos) << md;
  EXPECT_EQ(parsePpp(read("ppps/beta_q2_random_shrunk.ppp"), "shrunk.ppp"), shrunk.ppp);
  EXPECT_TRUE(fs::is_regular_file(dir_ + "/pictures/beta_q2_random_shrunk.png"));
  EXPECT_NE(read("report.html").find("<li>shrunk: 1 of 1 descriptors"), std::string::npos);
  // A planner's run (recorded: it plays only through ROS) is checked on its shrunk PPP through ROS instead.
  worst.recorded = true;
  input.worst = {worst};
  writeReport(dir_, input);
  EXPECT_NE(read("report.md").find("replay: `roslaunch launch/shrink.launch input:=ppps/beta_q2_random_shrunk.ppp "
                                   "agent:=random output:=check.ppp config:=EXPERIMENT.yaml args:=\"--seed 12345\"`"),
            std::string::npos)
      << read("report.md");
}

TEST_F(ReportTest, AFailureWithAnAnimationShowsItBesideThePictureAndWritesItsFile) {
  GifAnimation run(7, 5, {{255, 255, 255}, {0, 0, 0}});
  run.addFrame(std::vector<std::uint8_t>(35, 0), 10);
  const std::string gif = run.encode();
  ReportInput input = handMadeInput();
  input.failures[0].animation_gif = gif;
  FailureExample worst = input.failures[0];
  worst.agent = "explorer";
  worst.animation_gif.clear();  // an example without one shows the picture alone
  input.worst = {worst};
  writeReport(dir_, input);
  EXPECT_EQ(read("pictures/beta_q1_random.gif"), gif);
  EXPECT_FALSE(fs::exists(dir_ + "/pictures/beta_q1_explorer.gif"));
  const std::string md = read("report.md");
  EXPECT_NE(md.find("](pictures/beta_q1_random.png) ![The same run, step by step](pictures/beta_q1_random.gif)\n"),
            std::string::npos) << md;
  const std::string html = read("report.html");
  // Shown at twice its 7x5 size, each pixel doubled.
  const std::string embedded = "src=\"data:image/gif;base64," + generator::base64Encode(gif) + "\" width=\"14\" height=\"10\"";
  ASSERT_NE(html.find(embedded), std::string::npos);
  EXPECT_EQ(html.find(embedded, html.find(embedded) + 1), std::string::npos) << "one animation, embedded once";
  EXPECT_NE(html.find("animation <code>pictures/beta_q1_random.gif</code>"), std::string::npos);
  // The guide to the animations only where a section has one: the hardest PPPs here, not the faults found.
  const std::string guide = "Beside a picture, the same run step by step";
  const std::size_t faults = md.find("## Faults found"), hardest = md.find("## Hardest PPPs");
  EXPECT_EQ(md.substr(faults, hardest - faults).find(guide), std::string::npos);
  EXPECT_NE(md.substr(hardest).find(guide), std::string::npos);
}

TEST_F(ReportTest, AnAnimationThatIsNotAGifIsRefusedBeforeAnyFile) {
  ReportInput input = handMadeInput();
  input.failures[0].animation_gif = "\x89PNG....";
  try {
    writeReport(dir_, input);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(std::string(e.what()), "failures: example 0 (beta / q1 / random): its animation is not a GIF");
  }
  EXPECT_FALSE(fs::exists(dir_ + "/report.html"));
}

TEST_F(ReportTest, HtmlIsSelfContainedAndEscaped) {
  writeReport(dir_, handMadeInput());
  const std::string html = read("report.html");
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  EXPECT_EQ(html.find("src=\"/"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("data:image/png;base64,"), std::string::npos);
  // The embedded picture is the PNG file.
  const std::string png = read("pictures/beta_q1_random.png");
  EXPECT_NE(html.find("data:image/png;base64," + generator::base64Encode(png) + "\""), std::string::npos);
  // Escaping: title and configuration.
  EXPECT_NE(html.find("<title>Faults &lt;&amp;&gt; of agents</title>"), std::string::npos);
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  EXPECT_NE(html.find(">62.50%</td>"), std::string::npos);
  EXPECT_NE(html.find("ppp replay ppps/beta_q1.ppp --agent random --seed 12345 -o path.png"), std::string::npos);
}

TEST_F(ReportTest, PictureIsAPngOfTheProblemWithThePath) {
  const ReportInput input = handMadeInput();
  writeReport(dir_, input);
  const std::string png = read("pictures/beta_q1_random.png");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));

  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_memory(&image, png.data(), png.size())) << image.message;
  image.format = PNG_FORMAT_RGB;
  // 5 cells of 40 pixels plus the closing grid line.
  EXPECT_EQ(image.width, 201u);
  EXPECT_EQ(image.height, 201u);
  std::vector<std::uint8_t> rgb(PNG_IMAGE_SIZE(image));
  ASSERT_TRUE(png_image_finish_read(&image, nullptr, rgb.data(), 0, nullptr)) << image.message;

  PictureOptions options;
  options.cell_pixels = 40;
  EXPECT_EQ(rgb, renderProblemRgb(input.failures[0].ppp, input.failures[0].path, options));
  // The path is drawn: the centre of cell (1, 2) is path blue.
  const Pixel centre = cellCentre(Cell{1, 2}, options);
  const std::size_t at = (static_cast<std::size_t>(centre.y) * 201 + static_cast<std::size_t>(centre.x)) * 3;
  EXPECT_EQ((Rgb{rgb[at], rgb[at + 1], rgb[at + 2]}), kPathColour);
}

TEST_F(ReportTest, ARunInContinuousMotionIsDrawnAsItsTrajectoryAndReplayedThroughRos) {
  ReportInput input = handMadeInput();
  FailureExample worst = input.failures[0];
  worst.agent = "dwa";
  worst.recorded = true;
  worst.reason = reason::kCollision;
  // Three control periods from the start cell's centre, heading east, into the wall at x = 2.
  DrivenRun driven;
  driven.poses = {{0.5, 4.5, 0}, {1.0, 4.5, 0}, {1.5, 4.5, 0}, {1.8, 4.5, 0}};
  driven.radius = 0.2;
  driven.distance = 1.3;
  worst.driven = driven;
  worst.path = {{0, 0}, {1, 0}, {1, 0}, {1, 0}};
  input.worst = {worst};
  writeReport(dir_, input);
  const std::string md = read("report.md");
  EXPECT_NE(md.find("- path 3 control periods, 1.30 m driven, ending at (1.80, 4.50) m in the map frame, in cell "
                    "(1, 0)"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("replay: `roslaunch launch/shrink.launch input:=ppps/beta_q1.ppp agent:=dwa output:=check.ppp "
                    "config:=EXPERIMENT.yaml args:=\"--seed 12345\"`"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("A run in continuous motion is drawn as the robot centre's trajectory"), std::string::npos);
  // The picture is the trajectory's, not the cells'.
  const std::string png = read("pictures/beta_q1_dwa.png");
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_memory(&image, png.data(), png.size())) << image.message;
  image.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> rgb(PNG_IMAGE_SIZE(image));
  ASSERT_TRUE(png_image_finish_read(&image, nullptr, rgb.data(), 0, nullptr)) << image.message;
  PictureOptions options;
  options.cell_pixels = 40;
  EXPECT_EQ(rgb, renderTrajectoryRgb(worst.ppp, driven.poses, 1.0, 0.2, options));
  EXPECT_NE(rgb, renderProblemRgb(worst.ppp, worst.path, options));
}

TEST_F(ReportTest, UnsafeNamesAreSanitisedInFileNamesButShownInFull) {
  ReportInput input = handMadeInput();
  input.failures[0].set = "../be ta";
  input.failures[0].agent = "wall|follower";
  writeReport(dir_, input);
  // '/' and ' ' become '_'; a leading '.' gets a '_' in front so no name is hidden or climbs out.
  EXPECT_TRUE(fs::is_regular_file(dir_ + "/pictures/_.._be_ta_q1_wall_follower.png"));
  EXPECT_TRUE(fs::is_regular_file(dir_ + "/ppps/_.._be_ta_q1.ppp"));
  const std::string md = read("report.md");
  EXPECT_NE(md.find("`../be ta`"), std::string::npos);
  EXPECT_NE(md.find("--agent 'wall|follower'"), std::string::npos);
}

TEST_F(ReportTest, NoFailuresAndNoComparisonsStillMakeAReport) {
  ReportInput input = handMadeInput();
  input.failures.clear();
  input.comparisons.clear();
  input.config_text.clear();
  writeReport(dir_, input);
  const std::string md = read("report.md");
  EXPECT_NE(md.find("No set pairs were compared."), std::string::npos);
  EXPECT_NE(md.find("No failed runs on the hardest PPPs were recorded."), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ + "/pictures"));
}

TEST_F(ReportTest, UnknownComparedSetIsRejectedBeforeWritingAnything) {
  ReportInput input = handMadeInput();
  input.comparisons = {{"alpha", "gamma"}};
  try {
    writeReport(dir_, input);
    FAIL() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "comparisons");
    EXPECT_NE(std::string(e.what()).find("'gamma'"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir_));
}

TEST_F(ReportTest, PathOffTheGridIsRejectedNamingTheFailure) {
  ReportInput input = handMadeInput();
  input.failures[0].path.push_back(Cell{5, 4});
  try {
    writeReport(dir_, input);
    FAIL() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "failures");
    EXPECT_NE(std::string(e.what()).find("beta / q1 / random"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir_));
}

TEST_F(ReportTest, UnwritableDirectoryThrowsIoError) {
  EXPECT_THROW(writeReport("/proc/report-test-cannot-exist", handMadeInput()), IoError);
}

}  // namespace
}  // namespace ppp::simulator
