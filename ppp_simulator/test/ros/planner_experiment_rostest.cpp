// Planner agents end to end: simulator_node (started here) plays the bridges and planners of
// planner_experiment.test. The example planners pass their maps, the optimistic one as two instances sharing its
// runs as it plays them alone, one started after the simulator's step timeout loses no run; a silent planner, one publishing a path through a wall and one killed mid-episode
// fail with their reasons while the next episode runs; local planners answering with velocity commands pass,
// stick at a wall, or fail with the reason their commands earn; a bridge without a planner, or with a plan topic
// of the wrong type, exits naming the topics.
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <map>
#include <string>
#include <tuple>

#include "ppp_core/text_file.hpp"
#include "ppp_simulator/planner_moves.hpp"
#include "ppp_simulator/results_file.hpp"
#include "ros_test_support.hpp"

namespace ppp {
namespace simulator {
namespace {

using test::Child;
using test::scratch;

const std::string kTestDir = PPP_ROS_TEST_DIR;

/// Runs simulator_node on `config`; returns the rows of results.csv (the test fails when the node does).
std::vector<agents::EpisodeResult> runExperiment(const std::string& name, const std::string& config, std::string* out) {
  *out = scratch(name);
  Child simulator(std::string(SIMULATOR_NODE) + " __name:=sim_" + name + " _config:=" + kTestDir + "/" + config +
                      " _output_dir:=" + *out + " _record:=false _connect_timeout:=60 _planner_step_timeout:=15",
                  *out + ".log");
  const int status = simulator.wait();
  EXPECT_EQ(status, 0) << simulator.output();
  return status == 0 ? readResultsFile(*out + "/results.csv") : std::vector<agents::EpisodeResult>{};
}

/// reason[agent][problem] -> count.
std::map<std::string, std::map<std::string, std::map<std::string, int>>> reasons(
    const std::vector<agents::EpisodeResult>& rows) {
  std::map<std::string, std::map<std::string, std::map<std::string, int>>> out;
  for (const agents::EpisodeResult& r : rows) ++out[r.agent][r.problem][r.reason];
  return out;
}

TEST(PlannerExperimentTest, ExamplePlannersPassAndFaultyPlannersFailWithTheirReasons) {
  std::string out;
  auto rows = runExperiment("planners", "planner_experiment.yaml", &out);
  attachPlannerMoves(out + "/" + kPlannerMovesFile, &rows);
  ASSERT_EQ(rows.size(), 3u * 2 * 8 + 3u * 12);  // 3 maps; 8 agents of 2 runs, 12 of 1
  auto r = reasons(rows);
  for (const char* map : {"open", "wall", "hidden"}) {
    // OMPL plans on the true map; the optimistic re-planner starts blind and must find the route behind the
    // wall of "hidden" (its straight first plan runs into it).
    EXPECT_EQ(r["ompl"][map]["goal_reached"], 2) << map;
    EXPECT_EQ(r["optimistic"][map]["goal_reached"], 2) << map;
    EXPECT_EQ(r["optimistic_blocked"][map]["goal_reached"], 2) << map;
    EXPECT_EQ(r["late_planner"][map]["goal_reached"], 2) << map;  // no run lost while its planner started
    EXPECT_EQ(r["silent_planner"][map]["planner_timeout"], 1) << map;
    // A lockstep bridge moves only on an answer stamped with its request; a free-running one takes any path.
    EXPECT_EQ(r["unstamped_lockstep"][map]["planner_timeout"], 1) << map;
    EXPECT_EQ(r["unstamped_free"][map]["goal_reached"], 1) << map;
  }
  // Local planners: steering along a path passes; steering straight at the goal passes the open map and pushes
  // against the wall of the others until the budget is spent; a silent, a NaN and an absurdly fast command, and a
  // planner giving up (a status ABORTED), fail with their reasons.
  for (const char* map : {"open", "wall", "hidden"}) {
    EXPECT_EQ(r["cmd_vel_follow"][map]["goal_reached"], 2) << map;
    EXPECT_EQ(r["cmd_vel_silent"][map]["planner_timeout"], 1) << map;
    EXPECT_EQ(r["cmd_vel_nan"][map]["invalid_command"], 1) << map;
    EXPECT_EQ(r["cmd_vel_fast"][map]["invalid_command"], 1) << map;
    EXPECT_EQ(r["cmd_vel_give_up"][map]["planner_aborted"], 1) << map;
  }
  EXPECT_EQ(r["cmd_vel_straight"]["open"]["goal_reached"], 1);
  EXPECT_EQ(r["cmd_vel_straight"]["wall"]["budget_exhausted"], 1);
  EXPECT_EQ(r["cmd_vel_straight"]["hidden"]["budget_exhausted"], 1);
  // MRPT's reactive navigators on the open map, its goal in a corner: ND goes in; VFF turns back next to the goal
  // for ever (the map's edges repel it more than the goal attracts it), a loop proven endless since VFF answers
  // the same input the same way. ND remembers its last choice: none of its loops is claimed endless.
  EXPECT_EQ(r["reactive_nd"]["open"]["goal_reached"], 1);
  EXPECT_EQ(r["reactive_vff"]["open"]["budget_exhausted"], 1);
  EXPECT_EQ(r["straight_planner"]["open"]["goal_reached"], 1);
  EXPECT_EQ(r["straight_planner"]["wall"]["invalid_path"], 1);
  EXPECT_EQ(r["straight_planner"]["hidden"]["invalid_path"], 1);
  for (const agents::EpisodeResult& row : rows) {
    if (row.agent == "ompl") EXPECT_EQ(row.bumps, 0) << row.problem;
    // Straight at the goal from (0, 0) to (9, 0): four moves east, then bumps into the wall at x = 5 to the end.
    if (row.agent == "cmd_vel_straight" && row.problem != "open") {
      ASSERT_GE(row.actions.size(), 5u) << row.problem;
      for (int i = 0; i < 5; ++i) EXPECT_EQ(row.actions[i], Action::East) << row.problem << " action " << i;
      EXPECT_EQ(row.diagnosis, "stuck") << row.problem;
    }
    if (row.agent == "reactive_vff" && row.problem == "open") {
      EXPECT_EQ(row.diagnosis, "loop");
      EXPECT_EQ(row.loop_period, 2);
      EXPECT_GE(row.endless_step, 0);
    }
    if (row.agent == "reactive_nd") EXPECT_EQ(row.endless_step, -1) << row.problem;
    // Steering along a breadth-first path from (0, 0) to (9, 9) takes the 18 moves of a shortest route.
    if (row.agent == "cmd_vel_follow" && row.problem == "open") EXPECT_EQ(row.steps, 18);
    // Asked only when blocked, the robot still takes a shortest route where nothing blocks it.
    if (row.agent == "optimistic_blocked" && row.problem == "open") {
      EXPECT_EQ(static_cast<double>(row.steps), row.optimal_length);
    }
  }
  // Two instances sharing the runs play each run as one does, a bridge asking only on a change as one asking
  // at every step, and a bridge and planner as nodelets of one manager as processes of their own: the same moves
  // (the seeds differ with the name, and these planners draw nothing at random; the optimistic one keeps its plan
  // while the robot moves along it on an unchanged map).
  const std::map<std::string, std::string> twins = {{"optimistic_pair", "optimistic"},
                                                    {"optimistic_change", "optimistic"},
                                                    {"optimistic_nodelets", "optimistic"},
                                                    {"reactive_nd_nodelets", "reactive_nd"}};
  std::map<std::tuple<std::string, std::string, int>, const agents::EpisodeResult*> alone;
  for (const agents::EpisodeResult& row : rows) {
    if (row.agent == "optimistic" || row.agent == "reactive_nd") alone[{row.agent, row.problem, row.run}] = &row;
  }
  int shared = 0;
  for (const agents::EpisodeResult& row : rows) {
    const auto twin = twins.find(row.agent);
    if (twin == twins.end()) continue;
    ++shared;
    const agents::EpisodeResult& one = *alone.at({twin->second, row.problem, row.run});
    EXPECT_EQ(row.passed, one.passed) << row.agent << " " << row.problem << " run " << row.run;
    EXPECT_EQ(row.steps, one.steps) << row.agent << " " << row.problem << " run " << row.run;
    EXPECT_EQ(row.bumps, one.bumps) << row.agent << " " << row.problem << " run " << row.run;
    EXPECT_EQ(row.reason, one.reason) << row.agent << " " << row.problem << " run " << row.run;
    EXPECT_EQ(row.actions, one.actions) << row.agent << " " << row.problem << " run " << row.run;
    EXPECT_EQ(row.actions.size(), static_cast<std::size_t>(row.steps)) << row.agent << " " << row.problem;
  }
  EXPECT_EQ(shared, 6 + 6 + 6 + 3);
  // The planners' results are in the report beside any other agent's.
  const std::string report = readTextFile(out + "/report.md", 1u << 24);
  for (const char* agent : {"ompl", "optimistic", "silent_planner", "straight_planner"}) {
    EXPECT_NE(report.find(agent), std::string::npos) << agent;
  }
}

TEST(PlannerExperimentTest, APlannerKilledMidEpisodeFailsItAndTheNextEpisodeRuns) {
  std::string out;
  const auto rows = runExperiment("crash", "planner_crash_experiment.yaml", &out);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].reason, "planner_lost");
  EXPECT_GT(rows[0].steps, 0);  // it died after answering once: mid-episode
  EXPECT_EQ(rows[1].reason, "goal_reached");
  EXPECT_EQ(rows[2].reason, "goal_reached");
}

TEST(PlannerExperimentTest, TheBridgeNamesMissingPlannerTopicsAndWrongTypes) {
  const std::string out = scratch("bridge_errors");
  ros::NodeHandle nh;
  // A "planner" publishing odometry where the path should be.
  const ros::Publisher wrong = nh.advertise<nav_msgs::Odometry>("/typo/robot/plan", 1);
  const std::pair<std::string, std::string> cases[] = {
      {"__ns:=/lonely _connect_timeout:=1",
       "nothing publishes /lonely/robot/plan (nav_msgs/Path); nothing subscribes to "
       "/lonely/robot/move_base_simple/goal"},
      {"__ns:=/typo _connect_timeout:=5", "/typo/robot/plan is published as nav_msgs/Odometry; expected nav_msgs/Path"},
      {"__ns:=/local _interface:=cmd_vel _connect_timeout:=1",
       "nothing publishes /local/robot/cmd_vel (geometry_msgs/TwistStamped)"},
      {"__ns:=/bad _interface:=cmd_vel _lockstep:=false",
       "~interface: a cmd_vel planner is played in lockstep only (lockstep: true)"},
      {"__ns:=/bad _plan_timeout:=-1", "~plan_timeout: expected a number in [0.001, 86400], got -1"},
      {"__ns:=/bad _memory:=4x4", "~memory: the window side must be odd"},
      {"_connect_timeout:=1", "~name: required when the bridge runs outside an agent's namespace"},
  };
  int index = 0;
  for (const auto& c : cases) {
    Child bridge(std::string(PLANNER_BRIDGE_NODE) + " __name:=bridge_" + std::to_string(index) + " " + c.first,
                 out + "." + std::to_string(index++) + ".log");
    EXPECT_EQ(bridge.wait(), 1) << c.first;
    EXPECT_NE(bridge.output().find(c.second), std::string::npos) << c.first << " printed:\n" << bridge.output();
  }
}

}  // namespace
}  // namespace simulator
}  // namespace ppp

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "planner_experiment_rostest");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
