#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ppp_agents/agent.hpp"
#include "ppp_agents/planner_bridge_options.hpp"
#include "ppp_core/episode_options.hpp"
#include "ppp_core/option_spec.hpp"
#include "ppp_core/yaml_reader.hpp"

namespace ppp {
namespace agents {

/// Most runs per PPP of one agent in an experiment.
constexpr int kMaxRuns = 100000000;
/// Most instances (bridge and planner process pairs) of one planner agent.
constexpr int kMaxInstances = 64;

/// goal_seeking: as the agent type's design (every built-in type but random heads for the goal once noticed).
constexpr const char* kGoalSeekingByType = "by_type";
/// goal_seeking: once it has noticed the goal (goal_range), the agent takes a shortest path to it on its memory.
constexpr const char* kGoalSeekingOn = "on";
/// goal_seeking: the agent plays its strategy whether it has noticed the goal or not.
constexpr const char* kGoalSeekingOff = "off";

/// memory_model: the memory window is a k x k window around the agent.
constexpr const char* kMemoryModelWindow = "window";
/// memory_model: the memory keeps what the last k x k scans saw.
constexpr const char* kMemoryModelScans = "scans";
/// wall_start: before touching a wall, head for the goal.
constexpr const char* kWallStartGoal = "goal";
/// wall_start: before touching a wall, go straight on in a heading drawn at random.
constexpr const char* kWallStartRandom = "random";
/// wall_leave: a wall follower never lets go of the first wall it touched.
constexpr const char* kWallLeaveNever = "never";
/// wall_leave: a wall follower lets go of the wall as soon as its move towards the goal is free (Bug0).
constexpr const char* kWallLeaveGoalFree = "goal_free";

/// goal_ties: a wall follower heading for the goal as far across as down moves across.
constexpr const char* kGoalTiesHorizontal = "horizontal";
/// goal_ties: a wall follower heading for the goal as far across as down moves either way, drawn at random.
constexpr const char* kGoalTiesRandom = "random";

/// bumper_turn: after a bump, a bumper takes any of the three other directions.
constexpr const char* kBumperTurnOther = "other";
/// bumper_turn: after a bump, a bumper turns left or right, never straight back.
constexpr const char* kBumperTurnQuarter = "quarter";

/// explorer_idle: with nothing new in reach, the explorer moves to a random free neighbour.
constexpr const char* kExplorerIdleRandom = "random";
/// explorer_idle: with nothing new in reach, the explorer moves to the free neighbour it stood on least often.
constexpr const char* kExplorerIdleLeastVisited = "least_visited";
/// explorer_ties: of the neighbours revealing most, the explorer moves to one at random.
constexpr const char* kExplorerTiesRandom = "random";
/// explorer_ties: of the neighbours revealing most, the explorer moves to one nearest the goal, then at random.
constexpr const char* kExplorerTiesGoal = "goal";

/// frontier: the long-term explorer walks to the nearest frontier.
constexpr const char* kFrontierNearest = "nearest";
/// frontier: the long-term explorer walks to the frontier with the least walk to it plus distance on to the goal.
constexpr const char* kFrontierGoal = "goal";

/// wall_sense: a wall follower reads the wall beside it from its scan.
constexpr const char* kWallSenseScan = "scan";
/// wall_sense: a wall follower finds the wall by touch: it tries its moves in the hand-on-wall order and takes the
/// first that does not bump.
constexpr const char* kWallSenseTouch = "touch";

/// process: through ROS, a built-in agent's node runs in the experiment's nodelet manager (when the graph has one).
constexpr const char* kProcessManager = "manager";
/// process: through ROS, the agent's node runs in a process of its own.
constexpr const char* kProcessOwn = "own";

/// motion: the agent moves as the experiment's `motion` says.
constexpr const char* kMotionOfExperiment = "experiment";

/// One agent configuration of an experiment: a type plus handicaps, under a name of its own.
struct AgentConfig {
  std::string name;            ///< Name in results and reports (e.g. "explorer_memory_5x5"); defaults to type.
  std::string type;            ///< One of agentTypeNames().
  int memory_window = 0;       ///< Limited memory: keep only a k x k window around the agent (odd k); 0 = full.
  double sensor_noise = 0.0;   ///< Probability that a sensed cell is reported flipped (applied by the sensor).
  std::string goal_seeking = kGoalSeekingByType;  ///< kGoalSeekingByType, kGoalSeekingOn or kGoalSeekingOff.
  int goal_range = 0;          ///< Goal seekers: notice the goal within this many cells, walls or not; 0 = seen.
  std::string memory_model = kMemoryModelWindow;  ///< What memory KxK limits: kMemoryModelWindow or kMemoryModelScans.
  std::string wall_start = kWallStartGoal;        ///< Wall followers: kWallStartGoal or kWallStartRandom.
  std::string wall_leave = kWallLeaveNever;       ///< Wall followers: kWallLeaveNever or kWallLeaveGoalFree.
  std::string goal_ties = kGoalTiesHorizontal;    ///< Wall followers: kGoalTiesHorizontal or kGoalTiesRandom.
  std::string wall_sense = kWallSenseScan;        ///< Wall followers: kWallSenseScan or kWallSenseTouch.
  std::string bumper_turn = kBumperTurnOther;     ///< Bumpers: kBumperTurnOther or kBumperTurnQuarter.
  std::string explorer_idle = kExplorerIdleRandom;  ///< Explorers: kExplorerIdleRandom or kExplorerIdleLeastVisited.
  std::string explorer_ties = kExplorerTiesRandom;  ///< Explorers: kExplorerTiesRandom or kExplorerTiesGoal.
  std::string frontier = kFrontierNearest;          ///< Long-term explorers: kFrontierNearest or kFrontierGoal.
  int runs = 0;                ///< Runs per PPP for this agent; 0 = the experiment's `runs`.
  bool prior_map = false;      ///< Planner agents only: the planner is given the true map instead of the memory.
  std::string planner_node;    ///< Planner agents only: "package/executable" of the planner to start ("" = the user's).
  std::string planner_args;    ///< Planner agents only: arguments of planner_node ("_planning_time:=0.005 ...").
  BridgeOptions bridge;        ///< Planner agents only: its bridge's plan_timeout and cells_per_ppp_cell.
  int instances = 0;           ///< Planner agents and astar in continuous motion: nodes sharing its runs; 0 = instanceCount's.
  std::string host;            ///< Through ROS: the machine its node runs on ("" = the simulator's).
  std::string process = kProcessManager;  ///< Through ROS: kProcessManager or kProcessOwn.
  std::string motion = kMotionOfExperiment;  ///< kMotionOfExperiment, or a motion model of its own.
  /// @throws InvalidArgument naming "type" (listing the valid ones), "name", "memory", "sensor_noise",
  /// "goal_seeking", "goal_range", "memory_model", "wall_start", "wall_leave", "goal_ties", "wall_sense",
  /// "bumper_turn", "explorer_idle", "explorer_ties", "frontier", "runs", "prior_map", "planner_node",
  /// "planner_args", "plan_timeout", "cells_per_ppp_cell", "instances" or "host" (other agents have no planner:
  /// their bridge options are unused).
  void validate() const;
};

/// One declaration per agent option (YAML keys of an agents list, the agent node's and the bridge's `~`
/// parameters, the `ppp simulate` and `replay` flags; "type" is the flag --agent).
const std::vector<OptionSpec<AgentConfig>>& agentOptionSpecs();

/// The agent options an agent node reads as `~` parameters (and the experiment's graph writes for it).
const std::vector<OptionSpec<AgentConfig>>& agentNodeOptionSpecs();

/// The agent options that decide how one run plays (type, memory, sensor_noise, goal_seeking, goal_range,
/// memory_model, wall_start, wall_leave, goal_ties, wall_sense, bumper_turn, explorer_idle, explorer_ties,
/// frontier): the flags of `ppp simulate` and `ppp replay`, and of the replay commands a report gives.
const std::vector<OptionSpec<AgentConfig>>& agentPlayOptionSpecs();

/// The flags that make `ppp simulate` and `ppp replay` play `config` under `episode` ("--agent explorer --memory 5
/// --budget 100"): its type and every play option and episode rule that is not the default.
std::string replayFlags(const AgentConfig& config, const EpisodeOptions& episode);

/// The `ppp replay` command that plays run `seed` with `flags` (replayFlags()) on the PPP in `file` and draws it.
std::string replayCommand(const std::string& file, const std::string& flags, std::uint64_t seed);

/// The `ppp replay` command that plays `config`'s run `seed` under `episode` on the PPP in `file` and draws it.
std::string replayCommand(const std::string& file, const AgentConfig& config, const EpisodeOptions& episode,
                          std::uint64_t seed);

/// The type of agents played by an external ROS planner through planner_bridge_node, one episode at a time.
constexpr const char* kPlannerType = "planner";

/// True for an external planner agent (type kPlannerType), which cannot be built in-process.
bool isPlanner(const AgentConfig& config);

/// True when `config` plays in continuous motion under `options`: its own `motion`, else the experiment's.
bool playsContinuously(const AgentConfig& config, const EpisodeOptions& options);

/// A planner executable of this repository's, as the experiment's graph starts it.
struct ExamplePlanner {
  const char* nodelet;    ///< The nodelet it also builds as, or nullptr when it runs only as a process of its own.
  bool answers_messages;  ///< It answers each control period's messages (a local planner), with no timer of its own.
};

/// The planner executable `planner_node` ("package/executable") names, when it is this repository's, else nullptr.
const ExamplePlanner* examplePlanner(const std::string& planner_node);

/// What makes a planner agent's planner answer a control period (kWakesOnTimer or kWakesOnMessages): its
/// `wakes_on`, with auto resolved by its planner_node (this repository's local planners answer their messages).
std::string plannerWakesOn(const AgentConfig& config);

/// Which messages a control period sends the agent's planner (kPeriodMessagesEvery or kPeriodMessagesChanges): its
/// `period_messages`, with auto resolved by its planner_node (changes for this repository's local planners, unless
/// told to wake on a timer).
std::string plannerPeriodMessages(const AgentConfig& config);

/// The agent's bridge options with `wakes_on` and `period_messages` resolved (plannerWakesOn, plannerPeriodMessages):
/// what its bridge is told.
BridgeOptions plannerBridgeOptions(const AgentConfig& config);

/// How many instances play an agent's runs in parallel through ROS, each its share (every n-th run): for a planner
/// agent, bridge and planner pairs: `instances` when given, else as many as this machine has cores for a planner
/// the experiment starts (planner_node), and 1 for one the user starts. For a built-in agent in continuous motion
/// under `options`, agent nodes: `instances`, else as many as this machine has cores (one lockstep stream keeps
/// one core busy). 1 for every other agent (its node plays batches, and the experiment's other agents the cores).
int instanceCount(const AgentConfig& config, const EpisodeOptions& options);

/// The namespace of instance `instance` (0-based) of an agent played as `instances` instances, as a ROS graph
/// name: agentGraphName(name) for one instance, else agentGraphName(name) + "/instance_K" with K = instance + 1.
std::string instanceGraphName(const AgentConfig& config, int instance, int instances);

/// The built-in agent types of agentRegistry(), in its order (configurations may also name kPlannerType).
const std::vector<std::string>& agentTypeNames();

/// Builds an agent for a configuration (validated first). @throws InvalidArgument (also for planners).
std::unique_ptr<Agent> makeAgent(const AgentConfig& config);

/// False for agents that never look at their scan window (random, unless it seeks the goal): the simulator node
/// sends them none.
bool readsScanWindow(const AgentConfig& config);

/// Whether the agent heads for the goal once it has seen it: its goal_seeking, or its type's design.
bool seeksGoal(const AgentConfig& config);

/// The options of `config` a built-in agent plays with.
AgentBehaviour agentBehaviour(const AgentConfig& config);

/// True when the agent is given the true map at the start of each episode (astar, planners with prior_map).
bool givenPriorMap(const AgentConfig& config);

/// A memory window as configs write it: "KxK", or "full" for 0.
std::string memoryWindowText(int window);

/// Reads a list of agent configurations (each a mapping with name, type, memory, sensor_noise) from the
/// sequence under `key` of `reader`. @throws ParseError naming file, line and key.
std::vector<AgentConfig> readAgentConfigs(YamlMapReader& reader, const std::string& key);

/// Loads config/agents.yaml-style files: a mapping with the key `agents`. @throws IoError, ParseError.
std::vector<AgentConfig> loadAgentConfigs(const std::string& path);

/// The agent name as a legal ROS graph name (agent node name, topic namespace /NAME/..., tf prefix NAME/):
/// every character other than a letter, digit or '_' becomes '_', and a name not starting with a letter gets
/// the prefix "agent_" ("explorer_noise_0.1" -> "explorer_noise_0_1"). ROS-free, so that the simulator and
/// the launch files agree with the agent node on topic names.
std::string agentGraphName(const std::string& name);

}  // namespace agents
}  // namespace ppp
