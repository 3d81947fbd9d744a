// The ROS experiment end to end: simulator_node (started here as a child process) with agent nodes from
// ros_experiment.test. Checks the results equal `ppp experiment`'s, the bag, a resume after SIGKILL,
// faulty and killed agents, and bad parameters.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <nav_msgs/OccupancyGrid.h>
#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "ppp_core/option_cases.hpp"
#include "ppp_core/ppp_file.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_msgs/EpisodeResults.h"
#include "ppp_msgs/ProblemSet.h"
#include "ppp_msgs/conversions.h"
#include "ppp_msgs/node_parameters.h"
#include "ppp_simulator/experiment_graph.hpp"
#include "ppp_simulator/results_file.hpp"
#include "ros_test_support.hpp"
#include "simulator_parameters.hpp"

namespace ppp {
namespace simulator {
namespace {

namespace fs = std::filesystem;
using test::Child;
using test::nodePid;
using test::ResultCounter;
using test::scratch;

const std::string kTestDir = PPP_ROS_TEST_DIR;

std::string simulatorCommand(const std::string& name, const std::string& config, const std::string& out,
                             const std::string& extra = "") {
  return std::string(SIMULATOR_NODE) + " __name:=" + name + " _config:=" + config + " _output_dir:=" + out +
         " _batch_size:=7 _connect_timeout:=30 " + extra;
}

/// The reference: the same experiment run in process by `ppp experiment` (once per test binary).
const std::string& referenceRun() {
  static const std::string out = [] {
    const std::string dir = scratch("cli");
    const std::string command = std::string(PPP_CLI) + " experiment " + kTestDir + "/experiment.yaml -o " + dir +
                                " --quiet > /dev/null";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    return dir;
  }();
  return out;
}

TEST(RosExperimentTest, ResultsEqualTheInProcessRunAndTheBagHoldsTheMaps) {
  const std::string out = scratch("ros");
  Child simulator(simulatorCommand("sim_normal", kTestDir + "/experiment.yaml", out, "_record_problems:=1"),
                  out + ".log");
  ASSERT_EQ(simulator.wait(), 0) << simulator.output();
  EXPECT_EQ(readResultsFile(out + "/results.csv").size(), 2u * 3 * 3 * 40);
  EXPECT_EQ(readTextFile(out + "/results.csv", 1u << 26), readTextFile(referenceRun() + "/results.csv", 1u << 26))
      << "the ROS experiment's results differ from ppp experiment's";
  EXPECT_EQ(readTextFile(out + "/summary.csv", 1u << 26), readTextFile(referenceRun() + "/summary.csv", 1u << 26));
  EXPECT_TRUE(fs::exists(out + "/report.html"));

  // rosbag info shows the expected topics and types.
  const std::string info = out + "/bag_info.txt";
  ASSERT_EQ(std::system(("rosbag info " + out + "/experiment.bag > " + info).c_str()), 0);
  const std::string text = readTextFile(info, 1u << 20);
  for (const char* expected :
       {"/map ", "nav_msgs/OccupancyGrid", "/tf ", "tf2_msgs/TFMessage", "/astar/path", "nav_msgs/Path",
        "/explorer_memory_5x5/scan", "sensor_msgs/LaserScan", "/ppp/markers", "visualization_msgs/MarkerArray",
        "/ppp/results",
        "ppp_msgs/EpisodeResults", "/ppp/sets/turns", "ppp_msgs/ProblemSet"}) {
    EXPECT_NE(text.find(expected), std::string::npos) << "rosbag info lacks " << expected << ":\n" << text;
  }
  // The bag spans the recorded episodes (each step 0.1 s of bag time).
  // The line reads "duration:    12.3s", or "duration:    1:02s (62s)" from a minute up.
  const std::size_t duration_at = text.find("duration:");
  ASSERT_NE(duration_at, std::string::npos) << text;
  const std::string line = text.substr(duration_at, text.find('\n', duration_at) - duration_at);
  const std::size_t seconds_at = line.find('(') != std::string::npos ? line.find('(') + 1 : line.find_first_not_of(" ", 9);
  EXPECT_GT(std::atof(line.c_str() + seconds_at), 1.0) << line;
  // The random agent reads no window, so it is sent none and none is recorded.
  EXPECT_EQ(text.find("/random/scan"), std::string::npos) << text;
  // The first map in the bag is the first recorded PPP: set turns, ppp_000; compare cell by cell.
  rosbag::Bag bag(out + "/experiment.bag");
  rosbag::View maps(bag, rosbag::TopicQuery("/map"));
  ASSERT_GT(maps.size(), 0u);
  const auto map = maps.begin()->instantiate<nav_msgs::OccupancyGrid>();
  ASSERT_TRUE(map);
  const Grid grid = decodeGrid(readPppFile(out + "/sets/turns/ppp_000.ppp"));
  ASSERT_EQ(static_cast<int>(map->info.width), grid.width());
  ASSERT_EQ(static_cast<int>(map->info.height), grid.height());
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      EXPECT_EQ(map->data[(grid.height() - 1 - y) * grid.width() + x], grid.isObstacle(Cell{x, y}) ? 100 : 0);
    }
  }
  // Every result is in the bag once, grouped.
  std::size_t recorded = 0;
  std::set<std::string> keys;
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery("/ppp/results"))) {
    const auto group = m.instantiate<ppp_msgs::EpisodeResults>();
    ASSERT_TRUE(group);
    for (const ppp_msgs::EpisodeResult& r : group->results) {
      ++recorded;
      keys.insert(r.set + "/" + r.problem + "/" + r.agent + "/" + std::to_string(r.run));
    }
  }
  EXPECT_EQ(recorded, 2u * 3 * 3 * 40);
  EXPECT_EQ(keys.size(), 2u * 3 * 3 * 40);
}

TEST(RosExperimentTest, EvolvedSetsComeFromTheGeneratorNodesMessages) {
  // The reference run's sets, published as generator nodes publish them; the simulator's directory gets none.
  ros::NodeHandle nh;
  std::vector<ros::Publisher> publishers;
  for (const std::string name : {"turns", "difficulty"}) {
    const ProblemSet set = generator::readProblemSetDirectory(referenceRun() + "/sets/" + name);
    ppp_msgs::ProblemSet message;
    message.name = name;
    for (std::size_t i = 0; i < set.problems.size(); ++i) {
      message.problems.push_back(ppp_msgs::toMessage(set.problems[i], set.ids[i], 1.0));
    }
    publishers.push_back(nh.advertise<ppp_msgs::ProblemSet>(setTopic(name), 1, true));
    publishers.back().publish(message);
  }
  const std::string out = scratch("from_messages");
  Child simulator(simulatorCommand("sim_messages", kTestDir + "/experiment.yaml", out, "_generator_nodes:=true"),
                  out + ".log");
  ASSERT_EQ(simulator.wait(), 0) << simulator.output();
  EXPECT_FALSE(fs::exists(out + "/sets")) << "the simulator evolved or wrote sets itself";
  EXPECT_EQ(readTextFile(out + "/results.csv", 1u << 26), readTextFile(referenceRun() + "/results.csv", 1u << 26));
  rosbag::Bag bag(out + "/experiment.bag");
  rosbag::View view(bag, rosbag::TopicQuery("/ppp/sets/turns"));
  ASSERT_EQ(view.size(), 1u);
  EXPECT_EQ(view.begin()->instantiate<ppp_msgs::ProblemSet>()->problems.size(), 3u);
}

TEST(RosExperimentTest, RestartedSimulatorResumesAfterSigkill) {
  const std::string out = scratch("resume");
  ResultCounter counter;
  Child first(simulatorCommand("sim_resume_1", kTestDir + "/experiment.yaml", out, "_record:=false"), out + ".1.log");
  ASSERT_TRUE(counter.waitFor("random", 30, 120)) << "no progress: " << first.output();
  first.kill(SIGKILL);
  first.wait();
  const auto partial = readResultsFile(out + "/results.csv");
  EXPECT_LT(partial.size(), 2u * 3 * 3 * 40) << "the simulator finished before it was killed";
  Child second(simulatorCommand("sim_resume_2", kTestDir + "/experiment.yaml", out, "_record:=false"),
               out + ".2.log");
  ASSERT_EQ(second.wait(), 0) << second.output();
  EXPECT_NE(second.output().find("already done"), std::string::npos) << second.output();
  EXPECT_EQ(readTextFile(out + "/results.csv", 1u << 26), readTextFile(referenceRun() + "/results.csv", 1u << 26));
}

TEST(RosExperimentTest, SilentGarbageAndKilledAgentsFailWithReasonsAndTheRestCompletes) {
  const std::string out = scratch("faults");
  ResultCounter counter;
  Child simulator(simulatorCommand("sim_faults", kTestDir + "/fault_experiment.yaml", out,
                                   "_record:=false _step_timeout:=1.0 _timeouts_before_giving_up:=2"),
                  out + ".log");
  ASSERT_TRUE(counter.waitFor("doomed", 10, 120)) << "the doomed agent never finished a run: " << simulator.output();
  const int pid = nodePid("/doomed");
  ASSERT_GT(pid, 0);
  ASSERT_EQ(::kill(pid, SIGKILL), 0);
  ASSERT_EQ(simulator.wait(), 0) << simulator.output();
  const auto rows = readResultsFile(out + "/results.csv");
  ASSERT_EQ(rows.size(), 2u * 3 * 4 * 40);
  std::map<std::string, std::map<std::string, int>> reasons;
  for (const auto& r : rows) ++reasons[r.agent][r.reason];
  EXPECT_EQ(reasons["silent"]["timeout"], 240);
  EXPECT_EQ(reasons["garbage"]["invalid_action"], 240);
  EXPECT_GT(reasons["doomed"]["agent_lost"], 0);
  EXPECT_GT(reasons["doomed"]["budget_exhausted"] + reasons["doomed"]["goal_reached"], 0);
  EXPECT_EQ(reasons["healthy"]["budget_exhausted"] + reasons["healthy"]["goal_reached"], 240)
      << "the healthy agent's runs were disturbed by the others' faults";
}

TEST(RosExperimentTest, BadParametersStopTheNodeNamingThem) {
  const std::string out = scratch("bad");
  const std::pair<std::string, std::string> cases[] = {
      {"_config:=" + kTestDir + "/experiment.yaml _output_dir:=" + out + " _batch_size:=0",
       "~batch_size: expected an integer in [1, 100000], got 0"},
      {"_output_dir:=" + out, "~config: required"},
      {"_config:=/nonexistent/experiment.yaml _output_dir:=" + out, "/nonexistent/experiment.yaml: cannot open"},
      {"_config:=" + kTestDir + "/experiment.yaml", "~output_dir: required"},
      {"_config:=" + kTestDir + "/experiment.yaml _output_dir:=" + out + " _step_timeout:=-1",
       "~step_timeout: expected a number in [0.001, 86400], got -1"},
      {"_config:=" + kTestDir + "/bad_agent_experiment.yaml _output_dir:=" + out, "unknown agent type 'flier'"},
      {"_config:=" + kTestDir + "/experiment.yaml _output_dir:=" + out + " _generator_nodes:=true _set_timeout:=0.5",
       "/gen_turns/problem_set: no generator node publishes set 'turns' (node gen_turns"},
  };
  int index = 0;
  for (const auto& c : cases) {
    Child node(std::string(SIMULATOR_NODE) + " __name:=bad_sim_" + std::to_string(index) + " " + c.first,
               out + "." + std::to_string(index++) + ".log");
    EXPECT_NE(node.wait(), 0) << c.first;
    EXPECT_NE(node.output().find(c.second), std::string::npos) << c.first << " printed:\n" << node.output();
  }
}

TEST(RosExperimentTest, SimulatorParametersAndLaunchFileFlagsAcceptAndRefuseTheSameValues) {
  // Each declared simulator option, as a `~` parameter of the node and as a `ppp launch-file` flag.
  const std::string out = scratch("option_cases");
  int index = 0;
  for (const OptionCase& c : declaredOptionCases(simulatorOptionSpecs(), SimulatorOptions{})) {
    const std::string ns = "/simulator_option_case_" + std::to_string(index++);
    ros::param::set(ns + "/config", kTestDir + "/experiment.yaml");
    ros::param::set(ns + "/output_dir", out);
    ros::param::set(ns + "/" + c.option, ppp_msgs::yamlParameter(YAML::Load(c.value)));
    std::string error;
    try {
      readSimulatorParameters(ros::NodeHandle(ns));
    } catch (const Error& e) {
      error = e.what();
    }
    std::string flag = "--" + c.option;
    for (char& ch : flag) ch = ch == '_' ? '-' : ch;
    const std::string log = out + "." + std::to_string(index) + ".log";
    const std::string command = std::string(PPP_CLI) + " launch-file " + kTestDir + "/experiment.yaml -o " + out +
                                " " + flag + " '" + c.value + "' > /dev/null 2> " + log;
    const int status = std::system(command.c_str());
    const std::string flag_error = readTextFile(log, 1u << 16);
    if (c.accepted) {
      EXPECT_EQ(error, "") << c.option << " = " << c.value;
      EXPECT_EQ(status, 0) << command << ": " << flag_error;
    } else {
      EXPECT_EQ(error.rfind("~" + c.option + ": ", 0), 0u) << c.option << " = " << c.value << " gave: " << error;
      EXPECT_NE(status, 0) << command;
      EXPECT_NE(flag_error.find("error: " + flag + ": "), std::string::npos) << command << ": " << flag_error;
    }
  }
}

}  // namespace
}  // namespace simulator
}  // namespace ppp

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "ros_experiment_rostest");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
