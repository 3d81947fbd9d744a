#include "ppp_agents/agent_config.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "ppp_core/error.hpp"
#include "agent_option_cases.hpp"
#include "test_world.hpp"

namespace ppp {
namespace agents {
namespace {

using test::config;

const char* const kTypes =
    "astar, random, wall_follower_left, wall_follower_right, explorer, long_term_explorer, bumper, decision_bumper, "
    "planner";

/// The message of the InvalidArgument that `f` throws ("" when it throws none).
template <class F>
std::string invalidArgument(F f) {
  try {
    f();
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "";
}

/// The message of the ParseError that reading `yaml` (as file "agents.yaml") throws ("" when none).
std::string parseError(const std::string& yaml) {
  try {
    const YAML::Node root = YAML::Load(yaml);
    YamlMapReader reader(root, "agents.yaml");
    readAgentConfigs(reader, "agents");
    reader.rejectUnknownKeys();
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

std::vector<AgentConfig> read(const std::string& yaml) {
  const YAML::Node root = YAML::Load(yaml);
  YamlMapReader reader(root, "agents.yaml");
  return readAgentConfigs(reader, "agents");
}

TEST(AgentConfigTest, TypeNamesAreTheEightAgents) {
  std::string list;
  for (const std::string& name : agentTypeNames()) list += name + ", ";
  EXPECT_EQ(list + kPlannerType, kTypes);
}

TEST(AgentConfigTest, ValidateAcceptsEveryTypeAndTheHandicaps) {
  for (const std::string& type : agentTypeNames()) EXPECT_NO_THROW(config(type).validate()) << type;
  EXPECT_NO_THROW(config("explorer", 5, 0.1).validate());
  EXPECT_NO_THROW(config("explorer", 1, 1.0).validate());
  EXPECT_NO_THROW(config("explorer", 0, 0.0).validate());
}

TEST(AgentConfigTest, ValidateNamesTheBadOption) {
  EXPECT_EQ(invalidArgument([] { config("robot").validate(); }),
            std::string("type: unknown agent type 'robot'; valid: ") + kTypes);
  EXPECT_EQ(invalidArgument([] { config("").validate(); }), std::string("type: unknown agent type ''; valid: ") + kTypes);
  EXPECT_EQ(invalidArgument([] { config("explorer", 4).validate(); }),
            "memory: expected an odd window side in [1, 8191] (5 for 5x5) or 0 for full memory, got 4");
  EXPECT_EQ(invalidArgument([] { config("explorer", -3).validate(); }),
            "memory: expected an odd window side in [1, 8191] (5 for 5x5) or 0 for full memory, got -3");
  EXPECT_EQ(invalidArgument([] { config("explorer", 8193).validate(); }),
            "memory: expected an odd window side in [1, 8191] (5 for 5x5) or 0 for full memory, got 8193");
  EXPECT_EQ(invalidArgument([] { config("explorer", 0, 1.5).validate(); }),
            "sensor_noise: expected a number in [0, 1], got 1.5");
  EXPECT_EQ(invalidArgument([] { config("explorer", 0, -0.1).validate(); }),
            "sensor_noise: expected a number in [0, 1], got -0.1");
  EXPECT_EQ(invalidArgument([] { config("explorer", 0, std::nan("")).validate(); }),
            "sensor_noise: expected a number in [0, 1], got nan");
}

/// The memory window that the declared option `memory` reads from `text` (-1 when refused, with `problem` set).
int memoryWindow(const std::string& text, std::string* problem = nullptr) {
  const auto specs = selectOptions(agentOptionSpecs(), {"memory"});
  AgentConfig config;
  config.memory_window = -1;
  const std::string what = specs[0].set(&config, YAML::Node(text));
  if (problem != nullptr) *problem = what;
  return what.empty() ? config.memory_window : -1;
}

TEST(AgentConfigTest, ParsesMemoryWindows) {
  EXPECT_EQ(memoryWindow("5x5"), 5);
  EXPECT_EQ(memoryWindow("1x1"), 1);
  EXPECT_EQ(memoryWindow("21x21"), 21);
  EXPECT_EQ(memoryWindow("full"), 0);
  EXPECT_EQ(agentOptionSpecs()[2].text(config("explorer", 5)), "5x5");
  EXPECT_EQ(agentOptionSpecs()[2].text(config("explorer", 0)), "full");
}

TEST(AgentConfigTest, RejectsBadMemoryWindowsSayingWhy) {
  const std::string odd = "the window side must be odd and in [1, 8191] (the window is centred on the agent), got ";
  const std::string form = "expected KxK with odd K (e.g. 5x5) or 'full', got ";
  const auto problem = [](const std::string& text) {
    std::string what;
    EXPECT_EQ(memoryWindow(text, &what), -1) << text;
    return what;
  };
  EXPECT_EQ(problem("4x4"), odd + "'4x4'");
  EXPECT_EQ(problem("0x0"), odd + "'0x0'");
  EXPECT_EQ(problem("8193x8193"), odd + "'8193x8193'");
  EXPECT_EQ(problem("5x3"), "the window must be square (KxK), got '5x3'");
  EXPECT_EQ(problem("x"), form + "'x'");
  for (const char* bad : {"", "5", "5x", "x5", "5x5x5", " 5x5", "5X5", "-5x-5", "+5x+5", "fullx", "99999999999x1"}) {
    EXPECT_EQ(problem(bad), form + "'" + bad + "'");
  }
}

TEST(AgentConfigTest, ReadsConfigurationsWithDefaults) {
  const auto configs = read(
      "agents:\n"
      "  - {type: explorer}\n"
      "  - {name: tiny, type: explorer, memory: 3x3, sensor_noise: 0.25}\n"
      "  - name: whole\n"
      "    type: long_term_explorer\n"
      "    memory: full\n");
  ASSERT_EQ(configs.size(), 3u);
  EXPECT_EQ(configs[0].name, "explorer");
  EXPECT_EQ(configs[0].type, "explorer");
  EXPECT_EQ(configs[0].memory_window, 0);
  EXPECT_EQ(configs[0].sensor_noise, 0.0);
  EXPECT_EQ(configs[1].name, "tiny");
  EXPECT_EQ(configs[1].memory_window, 3);
  EXPECT_EQ(configs[1].sensor_noise, 0.25);
  EXPECT_EQ(configs[2].name, "whole");
  EXPECT_EQ(configs[2].type, "long_term_explorer");
  EXPECT_EQ(configs[2].memory_window, 0);
}

TEST(AgentConfigTest, RejectsBadYamlWithFileLineAndKey) {
  EXPECT_EQ(parseError("agents:\n  - {type: explorer, colour: red}\n"),
            "agents.yaml:2: agents[0].colour: unknown key; valid keys: bumper_turn, cells_per_ppp_cell, "
            "endless_proof, explorer_idle, explorer_ties, frontier, goal_range, goal_seeking, goal_ties, host, "
            "instances, interface, lockstep, memory, memory_model, motion, name, period_messages, plan_requests, plan_timeout, "
            "planner_args, "
            "planner_node, prior_map, process, runs, "
            "sensor_noise, type, wakes_on, wall_leave, wall_sense, wall_start");
  EXPECT_EQ(parseError("agents:\n  - {type: explorer}\n  - {name: lonely}\n"),
            std::string("agents.yaml:3: agents[1].type: missing; valid: ") + kTypes);
  EXPECT_EQ(parseError("agents:\n  - {type: explorer}\n  - name: x\n    type: robot\n"),
            std::string("agents.yaml:4: agents[1].type: unknown agent type 'robot'; valid: ") + kTypes);
  EXPECT_EQ(parseError("agents:\n  - {type: explorer, memory: 4x4}\n"),
            "agents.yaml:2: agents[0].memory: the window side must be odd and in [1, 8191] (the window is centred "
            "on the agent), got '4x4'");
  EXPECT_EQ(parseError("agents:\n  - {type: explorer, memory: 5x3}\n"),
            "agents.yaml:2: agents[0].memory: the window must be square (KxK), got '5x3'");
  EXPECT_EQ(parseError("agents:\n  - {type: explorer, memory: 5}\n"),
            "agents.yaml:2: agents[0].memory: expected KxK with odd K (e.g. 5x5) or 'full', got '5'");
  EXPECT_EQ(parseError("agents:\n  - {type: explorer, sensor_noise: 2}\n"),
            "agents.yaml:2: agents[0].sensor_noise: expected a number in [0, 1], got 2");
  EXPECT_EQ(parseError("agents:\n  - {type: explorer, sensor_noise: lots}\n"),
            "agents.yaml:2: agents[0].sensor_noise: expected a number, got 'lots'");
  EXPECT_EQ(parseError("agents:\n  - {type: explorer}\n  - {type: bumper}\n  - {type: explorer}\n"),
            "agents.yaml:4: agents[2].name: duplicate agent name 'explorer' (also agents[0]); give each "
            "configuration its own name");
  EXPECT_EQ(parseError("agents:\n  - {name: a, type: explorer}\n  - {name: a, type: bumper}\n"),
            "agents.yaml:3: agents[1].name: duplicate agent name 'a' (also agents[0]); give each configuration "
            "its own name");
  EXPECT_EQ(parseError("agents:\n  - {name: '', type: explorer}\n"),
            "agents.yaml:2: agents[0].name: expected a non-empty agent name");
  EXPECT_EQ(parseError("agents:\n  - explorer\n"), "agents.yaml:2: agents[0]: expected a mapping of key: value");
  EXPECT_EQ(parseError("agents: explorer\n"),
            "agents.yaml:1: agents: expected a list of agents, each a mapping with a type");
  EXPECT_EQ(parseError("agents: []\n"), "agents.yaml:1: agents: expected at least one agent");
  EXPECT_EQ(parseError("other: 1\n"), "agents.yaml:0: agents: missing; expected a list of agents");
  EXPECT_EQ(parseError("agents:\n  - {type: planner, runs: -1}\n"),
            "agents.yaml:2: agents[0].runs: expected an integer in [0, 100000000], got -1");
  EXPECT_EQ(parseError("agents:\n  - {type: planner, runs: many}\n"),
            "agents.yaml:2: agents[0].runs: expected an integer, got 'many'");
  EXPECT_EQ(parseError("agents:\n  - {type: explorer, prior_map: true}\n"),
            "agents.yaml:2: agents[0].prior_map: only planner agents take prior_map (astar always has the map; the "
            "other agents never do)");
}

TEST(AgentConfigTest, BehaviourOptionsMapToTheAgentsBehaviourAndOnlyWhereTheyApply) {
  for (const std::string& type : agentTypeNames()) {
    EXPECT_EQ(seeksGoal(config(type)), type != "random" && type != "astar") << type;
    EXPECT_EQ(agentBehaviour(config(type)).seek_goal, seeksGoal(config(type))) << type;
  }
  AgentConfig random = config("random");
  EXPECT_FALSE(readsScanWindow(random));  // the plain walker is sent no window
  random.goal_seeking = kGoalSeekingOn;
  EXPECT_TRUE(seeksGoal(random));
  EXPECT_TRUE(readsScanWindow(random));  // a seeker needs the window to see the goal
  AgentConfig explorer = config("explorer", 5);
  explorer.goal_seeking = kGoalSeekingOff;
  EXPECT_FALSE(agentBehaviour(explorer).seek_goal);
  EXPECT_EQ(agentBehaviour(explorer).memory_window, 5);
  EXPECT_EQ(parseError("agents:\n  - {type: explorer, goal_seeking: sometimes}\n"),
            "agents.yaml:2: agents[0].goal_seeking: unknown goal seeking 'sometimes'; valid: by_type, on, off");
  EXPECT_EQ(parseError("agents:\n  - {type: astar, goal_seeking: off}\n"),
            "agents.yaml:2: agents[0].goal_seeking: astar plans its route to the goal from the start; goal seeking "
            "does not apply");
  EXPECT_EQ(parseError("agents:\n  - {type: planner, memory_model: scans}\n"),
            "agents.yaml:2: agents[0].memory_model: a planner agent's memory is a window (the bridge's)");
  AgentConfig scans = config("explorer", 5);
  scans.memory_model = kMemoryModelScans;
  EXPECT_EQ(agentBehaviour(scans).memory_window, 0);
  EXPECT_EQ(agentBehaviour(scans).memory_scans, 25);
  EXPECT_EQ(agentBehaviour(config("explorer", 5)).memory_scans, 0);
  EXPECT_EQ(parseError("agents:\n  - {type: wall_follower_left, wall_sense: touch, wall_leave: goal_free}\n"),
            "agents.yaml:2: agents[0].wall_sense: a wall follower by touch cannot let go when the way to the goal is "
            "free (wall_leave: goal_free): it does not see it");
  EXPECT_EQ(parseError("agents:\n  - {type: wall_follower_left, wall_leave: sometimes}\n"),
            "agents.yaml:2: agents[0].wall_leave: unknown wall leave 'sometimes'; valid: never, goal_free");
  EXPECT_EQ(parseError("agents:\n  - {type: planner, goal_seeking: on}\n"),
            "agents.yaml:2: agents[0].goal_seeking: a planner agent's planner is given the goal; goal seeking does "
            "not apply");
}

TEST(AgentConfigTest, GoalRangeSetsTheBehaviourOfGoalSeekersOnly) {
  EXPECT_EQ(agentBehaviour(config("explorer")).goal_range, 0);
  EXPECT_EQ(read("agents:\n  - {type: bumper, goal_range: 3}\n")[0].goal_range, 3);
  EXPECT_EQ(agentBehaviour(read("agents:\n  - {type: bumper, goal_range: 3}\n")[0]).goal_range, 3);
  EXPECT_EQ(read("agents:\n  - {type: random, goal_seeking: on, goal_range: 3}\n")[0].goal_range, 3);
  EXPECT_EQ(parseError("agents:\n  - {type: random, goal_range: 3}\n"),
            "agents.yaml:2: agents[0].goal_range: only agents that head for the goal once they notice it take it "
            "(this one's goal_seeking is 'by_type', type random; goal_seeking: on makes it one)");
  EXPECT_EQ(parseError("agents:\n  - {type: explorer, goal_seeking: off, goal_range: 3}\n"),
            "agents.yaml:2: agents[0].goal_range: only agents that head for the goal once they notice it take it "
            "(this one's goal_seeking is 'off', type explorer; goal_seeking: on makes it one)");
  EXPECT_EQ(parseError("agents:\n  - {type: astar, goal_range: 3}\n"),
            "agents.yaml:2: agents[0].goal_range: only agents that head for the goal once they notice it take it "
            "(this one's goal_seeking is 'by_type', type astar)");
  EXPECT_EQ(parseError("agents:\n  - {type: explorer, goal_range: -1}\n"),
            "agents.yaml:2: agents[0].goal_range: expected an integer in [0, 4096], got -1");
}

TEST(AgentConfigTest, OptionsOfOneKindOfAgentSetItsBehaviourAndAreRefusedByOthers) {
  struct KindOption {
    const char* taker;    // a type that takes the option
    const char* setting;  // the option and its non-default value, as YAML
    bool AgentBehaviour::*flag;
    const char* refuser;  // a type that refuses it
    const char* refusal;
  };
  const KindOption options[] = {
      {"wall_follower_right", "wall_start: random", &AgentBehaviour::random_wall_start, "explorer",
       "wall_start: only wall followers take it"},
      {"wall_follower_left", "wall_leave: goal_free", &AgentBehaviour::leave_wall_for_goal, "bumper",
       "wall_leave: only wall followers take it"},
      {"wall_follower_right", "goal_ties: random", &AgentBehaviour::random_goal_ties, "explorer",
       "goal_ties: only wall followers take it"},
      {"wall_follower_left", "wall_sense: touch", &AgentBehaviour::walls_by_touch, "bumper",
       "wall_sense: only wall followers take it"},
      {"decision_bumper", "bumper_turn: quarter", &AgentBehaviour::quarter_turns, "wall_follower_left",
       "bumper_turn: only bumpers take it"},
      {"long_term_explorer", "explorer_idle: least_visited", &AgentBehaviour::idle_least_visited, "bumper",
       "explorer_idle: only explorers take it"},
      {"explorer", "explorer_ties: goal", &AgentBehaviour::goal_ties_for_gain, "random",
       "explorer_ties: only explorers take it"},
      {"long_term_explorer", "frontier: goal", &AgentBehaviour::frontier_towards_goal, "explorer",
       "frontier: only long-term explorers take it"},
  };
  for (const KindOption& o : options) {
    const std::string taker = std::string("agents:\n  - {type: ") + o.taker;
    EXPECT_FALSE(agentBehaviour(read(taker + "}\n")[0]).*o.flag) << o.setting;
    EXPECT_TRUE(agentBehaviour(read(taker + ", " + o.setting + "}\n")[0]).*o.flag) << o.setting;
    EXPECT_EQ(parseError(std::string("agents:\n  - {type: ") + o.refuser + ", " + o.setting + "}\n"),
              std::string("agents.yaml:2: agents[0].") + o.refusal);
  }
}

TEST(AgentConfigTest, YamlAcceptsAndRefusesWhatEverySourceDoes) {
  // The cases the agent node's parameters (agent_node_rostest) and the simulate flags (agent_flags_test) are
  // held to as well.
  for (const OptionCase& c : test::agentOptionCases(agentOptionSpecs())) {
    YAML::Node agent;
    agent["type"] = "explorer";
    agent[c.option] = YAML::Load(c.value);
    YAML::Node root;
    root["agents"].push_back(agent);
    std::string error;
    try {
      YamlMapReader reader(root, "agents.yaml");
      readAgentConfigs(reader, "agents");
    } catch (const ParseError& e) {
      error = e.what();
    }
    if (c.accepted) {
      EXPECT_EQ(error, "") << c.option << ": " << c.value;
    } else {
      EXPECT_NE(error.find(": agents[0]." + c.option + ": "), std::string::npos) << c.option << ": " << c.value
                                                                                 << " gave: " << error;
    }
  }
}

TEST(AgentConfigTest, PlannerAgentsAreReadButNeverBuiltInProcess) {
  const auto configs = read(
      "agents:\n"
      "  - {name: ompl, type: planner, runs: 3, prior_map: true}\n"
      "  - {type: planner, memory: 5x5}\n");
  ASSERT_EQ(configs.size(), 2u);
  EXPECT_TRUE(isPlanner(configs[0]));
  EXPECT_EQ(configs[0].runs, 3);
  EXPECT_TRUE(configs[0].prior_map);
  EXPECT_EQ(configs[1].name, "planner");
  EXPECT_EQ(configs[1].runs, 0);
  EXPECT_FALSE(configs[1].prior_map);
  EXPECT_EQ(configs[1].memory_window, 5);
  EXPECT_TRUE(readsScanWindow(configs[1]));
  EXPECT_EQ(invalidArgument([&] { makeAgent(configs[0]); }),
            "type: 'ompl' is a planner agent: an external ROS planner played through planner_bridge_node "
            "(docs/reference/planner-interface.md), never built in-process");
  AgentConfig astar = config("astar");
  astar.prior_map = true;
  EXPECT_EQ(invalidArgument([&] { astar.validate(); }),
            "prior_map: only planner agents take prior_map (astar always has the map; the other agents never do)");
}

TEST(AgentConfigTest, APlannerRunsAsInstancesEachInANamespaceOfItsOwn) {
  const auto configs = read(
      "agents:\n"
      "  - {name: mine.v2, type: planner, instances: 3}\n"
      "  - {name: started, type: planner, planner_node: ppp_agents/optimistic_planner_node}\n"
      "  - {name: by_hand, type: planner}\n"
      "  - {name: one, type: planner, planner_node: ppp_agents/optimistic_planner_node, instances: 1}\n"
      "  - {type: explorer}\n");
  const EpisodeOptions grid;
  EXPECT_EQ(instanceCount(configs[0], grid), 3);
  EXPECT_EQ(instanceGraphName(configs[0], 0, 3), "mine_v2/instance_1");
  EXPECT_EQ(instanceGraphName(configs[0], 2, 3), "mine_v2/instance_3");
  // A planner the experiment starts: one per core; one the user starts: one; 1 alone keeps the agent's namespace.
  const int cores = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, kMaxInstances);
  EXPECT_EQ(instanceCount(configs[1], grid), cores);
  EXPECT_EQ(instanceCount(configs[2], grid), 1);
  EXPECT_EQ(instanceGraphName(configs[2], 0, 1), "by_hand");
  EXPECT_EQ(instanceGraphName(configs[3], 0, 1), "one");
  EXPECT_EQ(instanceCount(configs[4], grid), 1);
  EXPECT_EQ(parseError("agents:\n  - {type: planner, instances: 65}\n").find("agents.yaml:2: agents[0].instances: "), 0u);
  EXPECT_EQ(parseError("agents:\n  - {type: explorer, instances: 2}\n"),
            "agents.yaml:2: agents[0].instances: only planner agents, and astar in continuous motion, run as several "
            "instances (the other agents' nodes play batches of runs)");
}

TEST(AgentConfigTest, AstarInContinuousMotionRunsAsInstancesOnlyThere) {
  const auto configs = read(
      "agents:\n"
      "  - {type: astar}\n"
      "  - {name: two, type: astar, instances: 2}\n"
      "  - {name: on_grid, type: astar, motion: grid}\n"
      "  - {name: own, type: astar, motion: continuous}\n");
  EpisodeOptions continuous;
  continuous.motion.motion = kMotionContinuous;
  const EpisodeOptions grid;
  const int cores = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, kMaxInstances);
  // One lockstep stream keeps one core busy: one agent node per core, unless the agent says how many.
  EXPECT_EQ(instanceCount(configs[0], continuous), cores);
  EXPECT_EQ(instanceCount(configs[1], continuous), 2);
  EXPECT_EQ(instanceCount(configs[2], continuous), 1);  // its own motion is the grid's
  EXPECT_EQ(instanceCount(configs[0], grid), 1);        // on the grid its node plays batches
  EXPECT_EQ(instanceCount(configs[1], grid), 1);
  EXPECT_EQ(instanceCount(configs[3], grid), cores);    // its own motion is continuous
}

TEST(AgentConfigTest, APlannerIsAskedEveryStepUnlessTheAgentSaysOtherwise) {
  const auto configs = read(
      "agents:\n"
      "  - {name: default, type: planner}\n"
      "  - {name: change, type: planner, plan_requests: on_change}\n"
      "  - {name: blocked, type: planner, plan_requests: on_blocked}\n"
      "  - {name: free, type: planner, lockstep: false}\n");
  EXPECT_EQ(configs[0].bridge.plan_requests, "every_step");
  EXPECT_TRUE(asksEveryStep(configs[0].bridge));
  EXPECT_FALSE(asksEveryStep(configs[1].bridge));
  EXPECT_TRUE(asksOnChange(configs[1].bridge));
  EXPECT_FALSE(asksEveryStep(configs[2].bridge));
  EXPECT_FALSE(asksOnChange(configs[2].bridge));
  EXPECT_FALSE(configs[3].bridge.lockstep);
  EXPECT_EQ(parseError("agents:\n  - {type: planner, plan_requests: sometimes}\n"),
            "agents.yaml:2: agents[0].plan_requests: unknown plan request rule 'sometimes'; valid: every_step, "
            "on_change, on_blocked");
  for (const char* rule : {"on_change", "on_blocked"}) {
    EXPECT_EQ(parseError(std::string("agents:\n  - {type: planner, lockstep: false, plan_requests: ") + rule + "}\n"),
              std::string("agents.yaml:2: agents[0].plan_requests: a free-running bridge (lockstep: false) asks "
                          "only when the robot's path is blocked; ") +
                  rule + " needs lockstep: true");
  }
  EXPECT_EQ(parseError("agents:\n  - {type: explorer, plan_requests: on_change}\n"),
            "agents.yaml:2: agents[0].plan_requests: only planner agents ask a planner for plans");
}

TEST(AgentConfigTest, ALocalPlannerAnswersWithVelocityCommandsInLockstepAtEveryStep) {
  const auto configs = read(
      "agents:\n"
      "  - {name: global, type: planner}\n"
      "  - {name: local, type: planner, interface: cmd_vel}\n");
  EXPECT_FALSE(commandsVelocity(configs[0].bridge));
  EXPECT_TRUE(commandsVelocity(configs[1].bridge));
  EXPECT_EQ(parseError("agents:\n  - {type: planner, interface: twist}\n"),
            "agents.yaml:2: agents[0].interface: unknown planner interface 'twist'; valid: path, cmd_vel");
  EXPECT_EQ(parseError("agents:\n  - {type: planner, interface: cmd_vel, lockstep: false}\n"),
            "agents.yaml:2: agents[0].interface: a cmd_vel planner is played in lockstep only (lockstep: true)");
  EXPECT_EQ(parseError("agents:\n  - {type: planner, interface: cmd_vel, plan_requests: on_change}\n"),
            "agents.yaml:2: agents[0].interface: a cmd_vel planner is asked at every step (it gives no path to move "
            "along), not on_change");
  EXPECT_EQ(parseError("agents:\n  - {type: bumper, interface: cmd_vel}\n"),
            "agents.yaml:2: agents[0].interface: only planner agents answer through a planner interface");
}

TEST(AgentConfigTest, OnlyAPlannerThatAnswersItsMessagesIsSentOnlyWhatChanged) {
  const auto configs = read(
      "agents:\n"
      "  - {name: nd, type: planner, interface: cmd_vel, planner_node: ppp_agents/mrpt_reactive_node}\n"
      "  - {name: nd_timer, type: planner, interface: cmd_vel, wakes_on: timer, "
      "planner_node: ppp_agents/mrpt_reactive_node}\n"
      "  - {name: mine, type: planner, interface: cmd_vel}\n"
      "  - {name: mine_told, type: planner, interface: cmd_vel, wakes_on: messages, period_messages: changes}\n");
  EXPECT_EQ(plannerPeriodMessages(configs[0]), kPeriodMessagesChanges);
  EXPECT_EQ(plannerPeriodMessages(configs[1]), kPeriodMessagesEvery);
  EXPECT_EQ(plannerPeriodMessages(configs[2]), kPeriodMessagesEvery);
  EXPECT_EQ(plannerPeriodMessages(configs[3]), kPeriodMessagesChanges);
  EXPECT_EQ(parseError("agents:\n  - {type: planner, interface: cmd_vel, period_messages: changes}\n"),
            "agents.yaml:2: agents[0].period_messages: changes needs a planner that answers each period's messages "
            "(wakes_on: messages): a period a timer overslept is asked again a control period later, and its "
            "planner could not tell it from the first of an episode whose map and goal it has not yet received");
  EXPECT_EQ(parseError("agents:\n  - {type: planner, interface: cmd_vel, period_messages: sometimes}\n"),
            "agents.yaml:2: agents[0].period_messages: unknown period messages 'sometimes'; valid: auto, every, "
            "changes");
  // A bridge started by hand resolves nothing: auto is every there, and changes needs wakes_on: messages.
  BridgeOptions bridge;
  bridge.base_frame = "robot/base_link";
  bridge.interface = kInterfaceCmdVel;
  bridge.period_messages = kPeriodMessagesChanges;
  EXPECT_NE(invalidArgument([&] { bridge.validate(); }).find("period_messages"), std::string::npos);
  bridge.wakes_on = kWakesOnMessages;
  EXPECT_EQ(invalidArgument([&] { bridge.validate(); }), "");
  bridge.period_messages = kPeriodMessagesAuto;
  EXPECT_FALSE(sendsChangesOnly(bridge));
}

TEST(AgentConfigTest, LoadRejectsUnknownTopLevelKeysAndMissingFiles) {
  const std::string path = ::testing::TempDir() + "agent_config_test_agents.yaml";
  {
    std::ofstream out(path);
    out << "agents:\n  - {type: astar}\nagent:\n  - {type: random}\n";
  }
  try {
    loadAgentConfigs(path);
    ADD_FAILURE() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), path + ":3: agent: unknown key; valid keys: agents");
  }
  EXPECT_THROW(loadAgentConfigs(path + ".missing"), IoError);
}

TEST(AgentConfigTest, ShippedConfigurationLoadsTheTenAgentsAndEightPlannerEntries) {
  const auto configs = loadAgentConfigs(std::string(PPP_CONFIG_DIR) + "/agents.yaml");
  struct Expected {
    const char* name;
    const char* type;
    int memory;
    double noise;
  };
  const std::vector<Expected> expected = {
      {"astar", "astar", 0, 0.0},
      {"random", "random", 0, 0.0},
      {"wall_follower_left", "wall_follower_left", 0, 0.0},
      {"wall_follower_right", "wall_follower_right", 0, 0.0},
      {"explorer", "explorer", 0, 0.0},
      {"long_term_explorer", "long_term_explorer", 0, 0.0},
      {"explorer_memory_5x5", "explorer", 5, 0.0},
      {"explorer_noise_0.1", "explorer", 0, 0.1},
      {"bumper", "bumper", 0, 0.0},
      {"decision_bumper", "decision_bumper", 0, 0.0},
      {"ompl", "planner", 0, 0.0},
      {"optimistic", "planner", 0, 0.0},
      {"mrpt", "planner", 0, 0.0},
      {"mrpt_nd", "planner", 0, 0.0},
      {"dwa", "planner", 0, 0.0},
      {"mrpt_nd_continuous", "planner", 0, 0.0},
      {"dwa_continuous", "planner", 0, 0.0},
      {"mrpt_tpspace", "planner", 0, 0.0},
  };
  ASSERT_EQ(configs.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(configs[i].name, expected[i].name) << i;
    EXPECT_EQ(configs[i].type, expected[i].type) << i;
    EXPECT_EQ(configs[i].memory_window, expected[i].memory) << i;
    EXPECT_EQ(configs[i].sensor_noise, expected[i].noise) << i;
    EXPECT_NO_THROW(configs[i].validate()) << i;
    // The planners' own runs: 3 on the grid, 1 in continuous motion (nothing random there).
    const bool driven = configs[i].motion == kMotionContinuous;
    EXPECT_EQ(configs[i].runs, isPlanner(configs[i]) ? (driven ? 1 : 3) : 0) << i;
    EXPECT_EQ(driven, i >= 15) << i;
  }
  EXPECT_TRUE(configs[10].prior_map);
  EXPECT_FALSE(configs[11].prior_map);
  EXPECT_EQ(configs[12].bridge.cells_per_ppp_cell, 4);
}

TEST(AgentConfigTest, GraphNamesAreLegalRosNames) {
  EXPECT_EQ(agentGraphName("explorer"), "explorer");
  EXPECT_EQ(agentGraphName("explorer_memory_5x5"), "explorer_memory_5x5");
  EXPECT_EQ(agentGraphName("explorer_noise_0.1"), "explorer_noise_0_1");
  EXPECT_EQ(agentGraphName("my-agent/2 b"), "my_agent_2_b");
  EXPECT_EQ(agentGraphName("5x5"), "agent_5x5");
  EXPECT_EQ(agentGraphName("_x"), "agent__x");
  EXPECT_EQ(agentGraphName(""), "agent_");
}

TEST(AgentConfigTest, MakeAgentBuildsEveryTypeAndEachPassesATinyMap) {
  const auto w = test::world({
      "S..",
      ".#.",
      "..G",
  });
  for (const std::string& type : agentTypeNames()) {
    for (int memory : {0, 5}) {
      std::unique_ptr<Agent> agent = makeAgent(config(type, memory));
      ASSERT_NE(agent, nullptr) << type;
      // The random agent needs luck; a budget of 2000 makes missing the goal of a 3x3 map vanishingly rare.
      const auto out = test::runEpisode(*agent, w, 7, 0.0, 2000, type == "astar");
      EXPECT_TRUE(out.passed) << type << " memory " << memory;
    }
  }
}

TEST(AgentConfigTest, MakeAgentValidatesFirst) {
  EXPECT_EQ(invalidArgument([] { makeAgent(config("robot")); }),
            std::string("type: unknown agent type 'robot'; valid: ") + kTypes);
  EXPECT_EQ(invalidArgument([] { makeAgent(config("explorer", 2)); }),
            "memory: expected an odd window side in [1, 8191] (5 for 5x5) or 0 for full memory, got 2");
}

TEST(AgentConfigTest, AstarWithoutPriorMapIsAnError) {
  const auto w = test::world({"S.", ".G"});
  auto agent = makeAgent(config("astar"));
  EXPECT_EQ(invalidArgument([&] { test::runEpisode(*agent, w, 1); }), "prior_map: the astar agent needs the prior map");
}

}  // namespace
}  // namespace agents
}  // namespace ppp
