// Wiring of generator_node: latched map and set, files equal to what it published and to a library run,
// the generate service, and bad parameters.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <ros/topic.h>

#include <nav_msgs/OccupancyGrid.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "generator_option_cases.hpp"
#include "generator_parameters.hpp"
#include "ppp_core/ppp_file.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_generator/evaluation_log.hpp"
#include "ppp_generator/genetic_algorithm.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_msgs/Generate.h"
#include "ppp_msgs/ProblemSet.h"
#include "ppp_msgs/node_parameters.h"

namespace ppp {
namespace generator {
namespace {

const ros::Duration kWait(60.0);

NodeParameters generatorParameters() { return readNodeParameters(ros::NodeHandle("/generator")); }

TEST(GeneratorNodeTest, LatchedMapEqualsTheChosenPppFile) {
  ros::NodeHandle nh;
  auto map = ros::topic::waitForMessage<nav_msgs::OccupancyGrid>("map", nh, kWait);
  ASSERT_TRUE(map) << "no latched map";
  auto set = ros::topic::waitForMessage<ppp_msgs::ProblemSet>("problem_set", nh, kWait);
  ASSERT_TRUE(set) << "no latched problem set";
  const NodeParameters parameters = generatorParameters();
  ASSERT_EQ(set->problems.size(), 8u);
  const std::string id = set->problems[parameters.publish_index].id;
  const Problem problem = readPppFile(parameters.output_dir + "/" + id + ".ppp");
  const Grid grid = decodeGrid(problem);
  ASSERT_EQ(map->info.width, 12u);
  ASSERT_EQ(map->info.height, 9u);
  EXPECT_DOUBLE_EQ(map->info.resolution, 0.5);
  EXPECT_EQ(map->header.frame_id, "map");
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      // Grid rows run down from the top; map rows run up from the bottom.
      const int expected = grid.isObstacle(Cell{x, y}) ? 100 : 0;
      EXPECT_EQ(map->data[(grid.height() - 1 - y) * grid.width() + x], expected) << x << "," << y;
    }
  }
}

TEST(GeneratorNodeTest, SetEqualsALibraryRunWithTheSameOptions) {
  ros::NodeHandle nh;
  auto set = ros::topic::waitForMessage<ppp_msgs::ProblemSet>("problem_set", nh, kWait);
  ASSERT_TRUE(set);
  const NodeParameters parameters = generatorParameters();
  GeneticAlgorithm ga(parameters.options);
  const ProblemSet expected = makeProblemSet(parameters.options, ga.run());
  ASSERT_EQ(expected.problems.size(), set->problems.size());
  for (std::size_t i = 0; i < expected.problems.size(); ++i) {
    EXPECT_EQ(set->problems[i].id, expected.ids[i]);
    const Problem written = readPppFile(parameters.output_dir + "/" + expected.ids[i] + ".ppp");
    EXPECT_EQ(formatPpp(written), formatPpp(expected.problems[i]));
  }
}

TEST(GeneratorNodeTest, ServiceEvolvesANewSet) {
  ros::NodeHandle nh;
  auto before = ros::topic::waitForMessage<ppp_msgs::ProblemSet>("problem_set", nh, kWait);
  ASSERT_TRUE(before);
  ASSERT_TRUE(ros::service::waitForService("/generator/generate", kWait));
  ppp_msgs::Generate call;
  call.request.seed = 7;
  ASSERT_TRUE(ros::service::call("/generator/generate", call));
  EXPECT_TRUE(call.response.success) << call.response.message;
  EXPECT_EQ(call.response.count, 8u);
  auto after = ros::topic::waitForMessage<ppp_msgs::ProblemSet>("problem_set", nh, kWait);
  ASSERT_TRUE(after);
  EXPECT_GT(after->header.stamp, before->header.stamp);
  bool differs = false;
  for (std::size_t i = 0; i < after->problems.size(); ++i) differs |= after->problems[i].map.data != before->problems[i].map.data;
  EXPECT_TRUE(differs) << "seed 7 gave the same set as seed 42";
}

TEST(GeneratorNodeTest, CommandLineWritesTheSameSetDirectory) {
  // Regenerate with the launch file's seed first: another test may have asked for a different one.
  ASSERT_TRUE(ros::service::waitForService("/generator/generate", kWait));
  ppp_msgs::Generate call;
  call.request.seed = 42;
  ASSERT_TRUE(ros::service::call("/generator/generate", call));
  ASSERT_TRUE(call.response.success) << call.response.message;
  const NodeParameters parameters = generatorParameters();
  const std::string cli_dir = parameters.output_dir + "_cli";
  // The same options as generator_node.test's parameters; everything else is config/generator.yaml's.
  const std::string command = std::string(PPP_CLI) +
                              " generate --quiet --fitness turns --population 8 --matings 200 --width 12 --height 9"
                              " --max-obstacles 6 --seed 42 -o " + cli_dir;
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const std::string diff = "diff -r " + parameters.output_dir + " " + cli_dir;
  EXPECT_EQ(std::system(diff.c_str()), 0) << "the node and ppp generate wrote different sets";
}

/// Runs a shell command; returns its exit status and (in `output`) what it printed.
int runCommand(const std::string& command, std::string* output) {
  FILE* pipe = ::popen(command.c_str(), "r");
  char buffer[512];
  while (pipe != nullptr && std::fgets(buffer, sizeof buffer, pipe) != nullptr) *output += buffer;
  return pipe == nullptr ? -1 : ::pclose(pipe);
}

/// Runs the node with one bad private parameter; returns its exit status and output.
int runWithParameter(const std::string& assignment, int index, std::string* output) {
  // A fresh node name per run, so no parameter of an earlier run is still set.
  return runCommand(std::string(GENERATOR_NODE) + " __name:=bad_generator_" + std::to_string(index) + " " +
                        assignment + " 2>&1",
                    output);
}

TEST(GeneratorNodeTest, AHuntWithoutEvaluatorPlaysItsPanelInProcessAsPppGenerateDoes) {
  const std::string dir = (std::filesystem::temp_directory_path() / "ppp_generator_node_hunt").string();
  std::filesystem::remove_all(dir);
  std::filesystem::remove_all(dir + "_cli");
  ros::param::set("/in_process_hunter/evaluator", std::string());  // no simulator: the node plays the panel
  std::string output;
  const int status = runCommand(std::string(GENERATOR_NODE) +
                                    " __name:=in_process_hunter _fitness:=failure _agents:=bumper,wall_follower_left"
                                    " _population:=6 _matings:=32 _runs_per_eval:=3 _budget:=60 _seed:=7"
                                    " _exit_when_done:=true _output_dir:=" + dir + " 2>&1",
                                &output);
  ASSERT_EQ(status, 0) << output;
  const std::string command = std::string(PPP_CLI) +
                              " generate --quiet --fitness failure --agents bumper,wall_follower_left --population 6"
                              " --matings 32 --runs-per-eval 3 --budget 60 --seed 7 -o " + dir + "_cli";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const std::string diff = "diff -r -x " + std::string(kEvaluationLogFile) + " " + dir + " " + dir + "_cli";
  EXPECT_EQ(std::system(diff.c_str()), 0) << "the node's in-process hunt and ppp generate wrote different sets";
  // The evaluation logs alike but for their wall times.
  const auto log = [](const std::string& set) {
    return withoutSeconds(readTextFile(set + "/" + kEvaluationLogFile, 1u << 24));
  };
  EXPECT_EQ(log(dir), log(dir + "_cli"));
}

TEST(GeneratorNodeTest, BadParametersStopTheNodeNamingThem) {
  const std::pair<const char*, const char*> cases[] = {
      {"_population:=1", "~population: expected an integer in [2, 100000], got 1"},
      {"_fitness:=hardest", "~fitness: unknown fitness 'hardest'; valid: turns"},
      {"_matings:=-5", "~matings: expected an integer in [0, 1000000000], got -5"},
      {"_width:=1", "~width: expected an integer in [2, 4096], got 1"},
      {"_max_obstacles:=-1", "~max_obstacles: expected an integer in [0, 1048576], got -1"},
      {"_characters:=all", "~characters: unknown character set 'all'"},
      {"_population:=many", "~population: expected an integer"},
      {"_publish_index:=99", "~publish_index: expected an index in [0, population = 60)"},
      {"_output_dir:=/proc/forbidden/set", "/proc/forbidden/set"},
  };
  int index = 0;
  for (const auto& c : cases) {
    std::string output;
    const int status = runWithParameter(c.first, index++, &output);
    EXPECT_NE(status, 0) << c.first;
    EXPECT_NE(output.find(c.second), std::string::npos) << c.first << " printed:\n" << output;
  }
}

TEST(GeneratorNodeTest, ShutdownMidGenerationStopsWithinASecondAndWritesNothing) {
  // What roslaunch does on shutdown: SIGINT to a node that is evolving a long set.
  const std::string dir = ::testing::TempDir() + "generator_shutdown_set";
  const std::string script = std::string(GENERATOR_NODE) + " __name:=long_generator _matings:=1000000000 _output_dir:=" +
                             dir + " _exit_when_done:=true > " + dir + ".log 2>&1 & pid=$!; sleep 2; " +
                             "start=$(date +%s%N); kill -INT $pid; wait $pid; " +
                             "echo \"$? $(( ($(date +%s%N) - start) / 1000000 ))\"";
  std::string output;
  ASSERT_EQ(runCommand("/bin/bash -c '" + script + "'", &output), 0) << output;
  int status = -1;
  long milliseconds = -1;
  ASSERT_EQ(std::sscanf(output.c_str(), "%d %ld", &status, &milliseconds), 2) << output;
  EXPECT_EQ(status, 0) << readTextFile(dir + ".log", 1u << 20);
  EXPECT_LE(milliseconds, 1000) << "the node took " << milliseconds << " ms to stop";
  EXPECT_FALSE(std::filesystem::exists(dir + "/set.csv"));
  EXPECT_NE(readTextFile(dir + ".log", 1u << 20).find("shut down mid-generation"), std::string::npos);
}

TEST(GeneratorNodeTest, ParametersAcceptAndRefuseWhatEverySourceDoes) {
  // The cases YAML (generator_options_test) and the flags (option_flags_test) are held to as well.
  int index = 0;
  for (const test::OptionCase& c : test::generatorOptionCases()) {
    std::string parameter = c.option;
    for (char& ch : parameter) ch = ch == '.' ? '/' : ch;
    const std::string ns = "/option_case_" + std::to_string(index++);
    ros::param::set(ns + "/" + parameter, ppp_msgs::yamlParameter(YAML::Load(c.value)));
    std::string error;
    try {
      readNodeParameters(ros::NodeHandle(ns));
    } catch (const Error& e) {
      error = e.what();
    }
    if (c.accepted) {
      EXPECT_EQ(error, "") << parameter << " = " << c.value;
    } else {
      EXPECT_EQ(error.rfind("~" + parameter + ": ", 0), 0u) << parameter << " = " << c.value << " gave: " << error;
    }
  }
}

}  // namespace
}  // namespace generator
}  // namespace ppp

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "generator_node_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
