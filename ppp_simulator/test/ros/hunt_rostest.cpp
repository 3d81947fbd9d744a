// Hunting through ROS: simulator_node in hunt mode (started here) evaluates candidate PPPs on the agent nodes
// and planner bridge of hunt.test. A hunt of built-in agents through generator_node writes the very set an
// in-process hunt writes; a planner that never answers gives failed evaluations with their reason, and the
// hunt against it ends; bad requests are refused naming what is wrong.
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "ppp_agents/agent_config.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_generator/evaluation_log.hpp"
#include "ppp_generator/set_evolution.hpp"
#include "ppp_msgs/EvaluateProblems.h"
#include "ppp_msgs/conversions.h"
#include "ppp_simulator/experiment_config.hpp"
#include "ppp_generator/failure_fitness.hpp"
#include "ros_test_support.hpp"

namespace ppp {
namespace simulator {
namespace {

namespace fs = std::filesystem;
using test::Child;
using test::scratch;

const std::string kTestDir = PPP_ROS_TEST_DIR;
const std::string kConfig = kTestDir + "/hunt_experiment.yaml";

/// The simulator node in hunt mode, for the whole test program.
class HuntTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const std::string log = scratch("simulator") + ".log";
    simulator_ = new Child(std::string(SIMULATOR_NODE) + " __name:=simulator _mode:=hunt _config:=" + kConfig +
                               " _connect_timeout:=60 _planner_step_timeout:=10",
                           log);
    ASSERT_TRUE(ros::service::waitForService("/simulator/evaluate", ros::Duration(60))) << simulator_->output();
  }
  static void TearDownTestSuite() {
    simulator_->kill(SIGINT);
    simulator_->wait();
    delete simulator_;
  }
  static Child* simulator_;
};
Child* HuntTest::simulator_ = nullptr;

/// Two hand-made 10x10 PPPs: open, and one with a wall.
std::vector<Problem> twoProblems() {
  Problem open = Problem::empty(10, 10, 1);
  open.goal = Cell{9, 9};
  Problem wall = open;
  wall.obstacles.push_back(Obstacle{Shape::VerticalBar, 5, 0, 8, 1});
  return {open, wall};
}

ppp_msgs::EvaluateProblems request(const std::vector<std::string>& agents, std::uint32_t runs) {
  ppp_msgs::EvaluateProblems call;
  for (const Problem& p : twoProblems()) call.request.problems.push_back(ppp_msgs::toMessage(p, "p", 1.0));
  call.request.agents = agents;
  call.request.runs = runs;
  call.request.seed = 7;
  return call;
}

TEST_F(HuntTest, BuiltInAgentsAreJudgedAsInProcessUnderRelativeBudgetsAndSoftFailures) {
  ppp_msgs::EvaluateProblems call = request({"wall_follower_left", "bumper"}, 6);
  ASSERT_TRUE(ros::service::call("/simulator/evaluate", call));
  ASSERT_EQ(call.response.error, "");
  ASSERT_EQ(call.response.evaluations.size(), 2u);
  // The same runs in process.
  const ExperimentConfig config = loadExperimentConfig(kConfig);
  generator::FailurePanel panel;
  panel.agents = generator::resolvePanel({"wall_follower_left", "bumper"}, config.agents);
  panel.episode = config.episode;
  panel.runs_per_eval = 6;
  panel.seed = 7;
  const std::vector<Problem> problems = twoProblems();
  std::vector<Grid> grids;
  for (const Problem& p : problems) grids.push_back(decodeGrid(p));
  const auto expected = generator::estimateFailures(panel, {&problems[0], &problems[1]}, {&grids[0], &grids[1]});
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(call.response.evaluations[i].failure_rate, expected[i].failure_rate) << i;
    EXPECT_EQ(call.response.evaluations[i].budget_used, expected[i].budget_used) << i;
    EXPECT_EQ(call.response.evaluations[i].regret, expected[i].regret) << i;
    EXPECT_EQ(call.response.evaluations[i].episodes, 12u);
  }
}

TEST_F(HuntTest, ASilentPlannerFailsEveryRunWithItsReason) {
  ppp_msgs::EvaluateProblems call = request({"silent_planner"}, 2);
  ASSERT_TRUE(ros::service::call("/simulator/evaluate", call));
  ASSERT_EQ(call.response.error, "");
  ASSERT_EQ(call.response.evaluations.size(), 2u);
  for (const ppp_msgs::ProblemEvaluation& e : call.response.evaluations) {
    EXPECT_EQ(e.failure_rate, 1.0);
    EXPECT_EQ(e.failed, 2u);
    ASSERT_EQ(e.reasons.size(), 1u);
    EXPECT_EQ(e.reasons[0], "planner_timeout");
    EXPECT_EQ(e.reason_counts[0], 2u);
    // A planner-reported ending is diagnosed as such; no loop, so none endless.
    EXPECT_EQ(e.diagnoses, std::vector<std::string>{"reported"});
    EXPECT_EQ(e.diagnosis_counts, std::vector<std::uint32_t>{2u});
    EXPECT_EQ(e.endless_loops, 0u);
    // Both runs fail the same way, on the start: one signature, named by the reason, no move from the start.
    ASSERT_EQ(e.signatures.size(), 1u);
    EXPECT_EQ(e.signatures[0].rfind("planner_timeout/", 0), 0u) << e.signatures[0];
    EXPECT_NE(e.signatures[0].find("/s0/"), std::string::npos) << e.signatures[0];
    EXPECT_EQ(e.signature_counts, std::vector<std::uint32_t>{2u});
  }
}

TEST_F(HuntTest, BadRequestsAreRefusedNamingWhatIsWrong) {
  ppp_msgs::EvaluateProblems call = request({"explorer"}, 1);
  ASSERT_TRUE(ros::service::call("/simulator/evaluate", call));
  EXPECT_EQ(call.response.error, "agents: unknown agent 'explorer'; valid: wall_follower_left, bumper, silent_planner");
  EXPECT_TRUE(call.response.evaluations.empty());
  call = request({}, 1);
  ASSERT_TRUE(ros::service::call("/simulator/evaluate", call));
  EXPECT_NE(call.response.error.find("agents: empty panel"), std::string::npos) << call.response.error;
  call = request({"bumper"}, 0);
  ASSERT_TRUE(ros::service::call("/simulator/evaluate", call));
  EXPECT_EQ(call.response.error, "runs: expected runs in [1, 10000], got 0");
  call = request({"bumper"}, 3);
  call.request.run_seeds = {1, 2};
  ASSERT_TRUE(ros::service::call("/simulator/evaluate", call));
  EXPECT_EQ(call.response.error, "run_seeds: expected one seed per run (3), got 2");
  call = request({"bumper"}, 1);
  call.request.problems[1].map.data[0] = 100;  // the map disagrees with the genotype
  ASSERT_TRUE(ros::service::call("/simulator/evaluate", call));
  EXPECT_FALSE(call.response.error.empty());
}

/// Runs generator_node as a hunter with `parameters`; returns its exit status.
int hunt(const std::string& name, const std::string& parameters, std::string* log_text) {
  Child hunter(std::string(GENERATOR_NODE) + " __name:=" + name + " _fitness:=failure _exit_when_done:=true " +
                   "_evaluator:=/simulator/evaluate " + parameters,
               scratch(name) + ".log");
  const int status = hunter.wait();
  *log_text = hunter.output();
  return status;
}

std::map<std::string, std::string> filesOf(const std::string& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    files[entry.path().filename().string()] = readTextFile(entry.path().string(), 1u << 24);
  }
  const auto log = files.find(generator::kEvaluationLogFile);  // its wall times differ from run to run
  if (log != files.end()) log->second = generator::withoutSeconds(log->second);
  return files;
}

TEST_F(HuntTest, AHuntThroughRosWritesTheSetAnInProcessHuntWrites) {
  const std::string out = scratch("ros_hunt");
  std::string log;
  ASSERT_EQ(hunt("hunter_built_in",
                 "_agents:=wall_follower_left,bumper _population:=8 _matings:=20 _runs_per_eval:=3 _seed:=5 "
                 "_output_dir:=" + out,
                 &log),
            0)
      << log;
  generator::GeneratorOptions options;
  options.fitness = generator::kFailureFitness;
  options.agents = {"wall_follower_left", "bumper"};
  options.population = 8;
  options.matings = 20;
  options.runs_per_eval = 3;
  options.seed = 5;
  const ExperimentConfig config = loadExperimentConfig(kConfig);
  const std::string in_process = scratch("in_process_hunt");
  generator::evolveSetDirectory(in_process, options, generator::fitnessFor(options, config.agents, config.episode, 1));
  EXPECT_EQ(filesOf(out), filesOf(in_process));
}

TEST_F(HuntTest, AHuntAgainstASilentPlannerEndsWithEveryPppFailed) {
  const std::string out = scratch("silent_hunt");
  std::string log;
  ASSERT_EQ(hunt("hunter_silent",
                 "_agents:=silent_planner _population:=3 _matings:=1 _runs_per_eval:=1 _output_dir:=" + out, &log),
            0)
      << log;
  const ProblemSet set = generator::readProblemSetDirectory(out);
  ASSERT_EQ(set.problems.size(), 3u);
  for (double value : set.fitness_values) EXPECT_EQ(value, 1.0);
  EXPECT_NE(log.find("failed as planner_timeout"), std::string::npos) << log;
}

}  // namespace
}  // namespace simulator
}  // namespace ppp

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "hunt_test");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
