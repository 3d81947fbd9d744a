#include "ppp_simulator/experiment_graph.hpp"

#include <algorithm>
#include <set>

#include "ppp_agents/continuous/continuous_agent.hpp"
#include "ppp_core/csv.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/motion_options.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_generator/fitness.hpp"
#include "ppp_agents/planner_bridge_options.hpp"
#include "ppp_generator/generator_node_options.hpp"
#include "ppp_msgs/graph_names.h"
#include "ppp_msgs/launch_graph.h"

namespace ppp {
namespace simulator {

namespace {

/// The roslaunch param type of a declared option with `value` ("int", "double", "bool", "yaml" for a list; else
/// "str", as for an integer beyond XML-RPC's 32 bits, a 64-bit seed say).
template <typename Options>
std::string parameterType(const OptionSpec<Options>& spec, const std::string& value) {
  switch (spec.kind) {
    case OptionKind::Integer: {
      const bool fits = value.size() < 10 || (value.size() == 10 && value <= "2147483647") ||
                        (value.size() == 11 && value[0] == '-' && value <= "-2147483648");
      return fits ? "int" : "str";
    }
    case OptionKind::Number: return "double";
    case OptionKind::Boolean: return "bool";
    case OptionKind::TextList: return "yaml";  // its plain text is a YAML flow list
    default: return "str";
  }
}

/// Appends one param per declared option of `specs`, with its value in `values` (strings unquoted).
template <typename Options>
void addParams(const std::vector<OptionSpec<Options>>& specs, const Options& values, ppp_msgs::GraphNode* node) {
  for (const OptionSpec<Options>& spec : specs) {
    const std::string value = spec.plainText(values);
    node->params.push_back({spec.name, parameterType(spec, value), value});
  }
}

/// Tells a planner in continuous motion the robot it drives: its kinematics, limits and control period (as the
/// motion options name them) and robot_radius in metres.
void addRobotParams(const EpisodeOptions& episode, ppp_msgs::GraphNode* planner) {
  static const std::vector<OptionSpec<MotionOptions>> robot =
      selectOptions(motionOptionSpecs(), {"kinematics", "max_linear_speed", "max_angular_speed",
                                          "max_linear_acceleration", "max_angular_acceleration", "control_period"});
  addParams(robot, episode.motion, planner);
  planner->params.push_back(
      {"robot_radius", "double", formatNumber(episode.robot_radius * episode.motion.resolution)});
}

/// The remapping of `topic` under the node's own name.
ppp_msgs::GraphRemap privateTopic(const char* topic) { return {topic, std::string("~") + topic}; }

/// The machine name of a host.
std::string machineName(const std::string& host) { return "host_" + agents::agentGraphName(host); }

/// The machine of an agent on another host, or "".
std::string machineOf(const agents::AgentConfig& agent) { return agent.host.empty() ? "" : machineName(agent.host); }

/// A generator node for `set` of the experiment writing to `experiment_dir`, its set to `output_dir`; a hunt's is
/// required and exits when its set is written. A set that starts from another evolved set waits for its
/// generator. @throws InvalidArgument("initial_pool", ...) for a hunt that would wait for a set nobody evolves.
ppp_msgs::GraphNode generatorNode(const ExperimentConfig& config, const SetSpec& set,
                                  const std::string& experiment_dir, const std::string& output_dir, bool hunt) {
  generator::GeneratorNodeOptions options;
  options.options_yaml = generator::generatorOptionsYaml(generatorOptionsIn(config, set, experiment_dir));
  const SetSpec* start = findSet(config, set.generator->initial_pool);
  if (start && start->generator) {
    if (hunt) {
      throw InvalidArgument("initial_pool", "set '" + set.name + "' starts from set '" + start->name +
                                                "', which a hunt alone does not evolve: run the experiment, or give "
                                                "initial_pool a directory");
    }
    options.wait_for_set = setTopic(start->name);
  }
  options.set_name = set.name;
  options.output_dir = output_dir;
  options.resume = true;
  options.exit_when_done = hunt;
  ppp_msgs::GraphNode node{"ppp_generator", "generator_node", generatorNodeName(set.name)};
  node.required = hunt;
  addParams(generator::generatorNodeOptionSpecs(), options, &node);
  node.remaps = {privateTopic(ppp_msgs::topics::kProblemSet), privateTopic(ppp_msgs::topics::kMap)};
  return node;
}

/// Makes `node` the nodelet `type` in `manager` (when there is one), named from the node's namespace.
void loadInto(const std::string& manager, const std::string& type, ppp_msgs::GraphNode* node) {
  if (manager.empty()) return;
  node->nodelet = type;
  node->manager = node->group.empty() && node->ns.empty() ? manager : "/" + manager;
}

/// True when `agent`'s nodes may load into the experiment's manager: it asks for no process of its own and runs on
/// this host.
bool inManager(const agents::AgentConfig& agent) {
  return agent.process == agents::kProcessManager && agent.host.empty();
}

/// The agent node of each instance of `agent` (agents::instanceCount: one, but for astar in continuous motion), as
/// /NAME or /NAME/instance_K; nodelets in `manager` ("" for none) unless the agent asks for processes of their own
/// or runs on another host.
std::vector<ppp_msgs::GraphNode> agentNodes(const agents::AgentConfig& agent, const EpisodeOptions& episode,
                                            const std::string& manager) {
  const int instances = agents::instanceCount(agent, episode);
  std::vector<ppp_msgs::GraphNode> nodes;
  for (int instance = 0; instance < instances; ++instance) {
    const std::string name = agents::instanceGraphName(agent, instance, instances);
    const std::size_t slash = name.rfind('/');
    ppp_msgs::GraphNode node{"ppp_agents", "agent_node", name.substr(slash + 1)};
    if (slash != std::string::npos) node.group = name.substr(0, slash);
    if (inManager(agent)) loadInto(manager, "ppp_agents/Agent", &node);
    node.machine = machineOf(agent);
    node.agent = agent.name;
    addParams(agents::agentNodeOptionSpecs(), agent, &node);
    node.remaps = {privateTopic(ppp_msgs::topics::kScans), privateTopic(ppp_msgs::topics::kMoves)};
    if (agents::movesContinuously(agent)) {
      node.remaps.push_back(privateTopic(ppp_msgs::topics::kSensing));
      node.remaps.push_back(privateTopic(ppp_msgs::topics::kCommands));
    }
    nodes.push_back(node);
  }
  return nodes;
}

/// How long a planner agent's bridges wait for their planner: five minutes for one the user starts by hand, 20 s
/// for one the graph starts.
double plannerConnectTimeout(const agents::AgentConfig& agent) {
  const std::size_t slash = agent.planner_node.find('/');
  const bool by_hand = slash == std::string::npos || slash + 1 == agent.planner_node.size();
  return by_hand ? 300.0 : 20.0;
}

/// Seconds the simulator waits for a planner agent beyond its bridge's wait for the planner: the bridge's own start.
constexpr double kBridgeConnectMargin = 10.0;

/// The clock a node on simulated time reads.
constexpr const char* kClock = "/clock";
/// Where the graph's nodes that keep the system's time look for /use_sim_time (a parameter nobody sets).
constexpr const char* kSystemTimeParameter = "/ppp/use_system_time";

/// True for a planner agent playing in continuous motion: its planner runs on the simulated time its bridge
/// publishes.
bool playsOnSimulatedTime(const agents::AgentConfig& agent, const EpisodeOptions& episode) {
  return agents::isPlanner(agent) && agents::playsContinuously(agent, episode);
}

/// The bridge of each instance of a planner agent (told the robot's radius) and, when the config names it, its
/// planner, in the instance's namespace (agents::instanceGraphName); nodelets of `manager` ("" for none) unless the
/// agent asks for processes of its own or runs on another host (and the planner, unless it is one of ours).
std::vector<ppp_msgs::GraphNode> plannerNodes(const agents::AgentConfig& agent, const EpisodeOptions& episode,
                                              const std::string& manager) {
  const std::string in_manager = inManager(agent) ? manager : "";
  const bool simulated_time = playsOnSimulatedTime(agent, episode);
  const std::size_t slash = agent.planner_node.find('/');
  const std::string package = agent.planner_node.substr(0, slash);
  const std::string type = slash == std::string::npos ? "" : agent.planner_node.substr(slash + 1);
  agents::BridgeOptions options = agents::plannerBridgeOptions(agent);
  options.connect_timeout = plannerConnectTimeout(agent);
  options.robot_radius = episode.robot_radius;
  static const std::vector<OptionSpec<agents::AgentConfig>> named =
      selectOptions(agents::agentNodeOptionSpecs(), {"name", "memory"});
  static const std::vector<OptionSpec<agents::BridgeOptions>> written =
      selectOptions(agents::bridgeOptionSpecs(),
                    {"plan_timeout", "lockstep", "plan_requests", "interface", "endless_proof", "wakes_on",
                     "period_messages", "connect_timeout", "cells_per_ppp_cell", "robot_radius"});
  std::vector<ppp_msgs::GraphNode> nodes;
  const int instances = agents::instanceCount(agent, episode);
  for (int instance = 0; instance < instances; ++instance) {
    ppp_msgs::GraphNode bridge{"ppp_agents", "planner_bridge_node", ppp_msgs::nodes::kBridge};
    bridge.group = agents::instanceGraphName(agent, instance, instances);
    bridge.machine = machineOf(agent);
    bridge.agent = agent.name;
    addParams(named, agent, &bridge);
    addParams(written, options, &bridge);
    if (type.empty()) {  // the user starts the planner, on the global /tf
      loadInto(in_manager, "ppp_agents/PlannerBridge", &bridge);
      nodes.push_back(bridge);
      continue;
    }
    // The bridge and the planner it started talk tf in their own namespace: on the global /tf every planner would
    // take every instance's and every other planner's poses, a cost per step growing with their number.
    const std::string ns = "/" + bridge.group + "/";
    bridge.remaps = {{"/tf", ns + "tf"}, {"/tf_static", ns + "tf_static"}};
    loadInto(in_manager, "ppp_agents/PlannerBridge", &bridge);
    nodes.push_back(bridge);
    ppp_msgs::GraphNode planner{package, type, ppp_msgs::nodes::kPlanner};
    planner.group = bridge.group;
    planner.ns = ppp_msgs::topics::kRobotNamespace;
    planner.machine = bridge.machine;
    planner.agent = agent.name;
    planner.args = agent.planner_args;
    planner.remaps = bridge.remaps;
    const agents::ExamplePlanner* example = agents::examplePlanner(agent.planner_node);
    const bool nodelet = example != nullptr && example->nodelet != nullptr && !in_manager.empty();
    if (simulated_time) addRobotParams(episode, &planner);
    if (simulated_time && !nodelet) {
      // Its own clock, which its bridge publishes; a process of its own, as a process has one time for all its nodes.
      // This repository's planners that build as nodelets read the time from the stamps of what they answer, so
      // they join the manager beside their bridge, which asks them in the simulator's thread.
      planner.remaps.push_back({kClock, ns + ppp_msgs::topics::kRobotNamespace + "/" + ppp_msgs::topics::kPlannerClock});
    }
    if (nodelet) loadInto(in_manager, example->nodelet, &planner);
    nodes.push_back(planner);
  }
  return nodes;
}

/// The set a hunt graph evolves. @throws InvalidArgument naming "hunt" unless it is a set of `config` evolved with a
/// panel fitness.
const SetSpec& huntedSet(const ExperimentConfig& config, const std::string& name) {
  std::vector<std::string> hunted;
  for (const SetSpec& set : config.sets) {
    if (!set.generator || !generator::isPanelFitness(set.generator->fitness)) continue;
    if (set.name == name) return set;
    hunted.push_back(set.name);
  }
  throw InvalidArgument("hunt", "the config has no set '" + name + "' evolved with a panel fitness (its hunted sets: " +
                                    (hunted.empty() ? "none" : joinNames(hunted)) + ")");
}

/// Puts the nodelet manager the nodelets of `graph` name first; the manager is required when one of them is (the
/// graph then ends when the manager does, and that nodelet's exit status is its private exit_status parameter).
void addManager(ppp_msgs::LaunchGraph* graph) {
  ppp_msgs::GraphNode manager{"nodelet", "nodelet", ppp_msgs::nodes::kManager};
  manager.args = "manager";
  for (ppp_msgs::GraphNode& node : graph->nodes) {
    if (node.nodelet.empty() || !node.required) continue;
    node.required = false;
    manager.required = true;
    graph->status_param = "/" + node.name + "/exit_status";
  }
  graph->nodes.insert(graph->nodes.begin(), manager);
}

/// The shrink node of `task` (required: the graph ends with it).
ppp_msgs::GraphNode shrinkNode(const ShrinkTask& task) {
  ppp_msgs::GraphNode node{"ppp_simulator", "shrink_node", ppp_msgs::nodes::kShrink};
  node.required = true;
  addParams(shrinkTaskSpecs(), task, &node);
  return node;
}

/// Checks the shrink of `options` against `config`. @throws InvalidArgument naming "hunt" (both asked for),
/// "agent" (not the config's) or the option.
void checkShrink(const ExperimentConfig& config, const GraphOptions& options) {
  if (!options.hunt.empty()) throw InvalidArgument("hunt", "a graph hunts or shrinks, not both");
  options.shrink.validate();
  const agents::AgentConfig& agent = configAgent(config, options.shrink.agent);
  if (!agents::isPlanner(agent)) agents::refuseContinuous(agent, config.episode);  // planners shrink in both models
}

/// The check node of `task` (required: the graph ends with it).
ppp_msgs::GraphNode checkNode(const CheckTask& task) {
  ppp_msgs::GraphNode node{"ppp_simulator", "check_node", ppp_msgs::nodes::kCheck};
  node.required = true;
  addParams(checkTaskSpecs(), task, &node);
  return node;
}

/// Checks the check of `options` against `config`. @throws InvalidArgument naming "check" (a hunt or shrink asked
/// for too), "agent" (not the config's) or the option.
void checkCheck(const ExperimentConfig& config, const GraphOptions& options) {
  if (!options.hunt.empty() || !options.shrink.input.empty()) {
    throw InvalidArgument("check", "a graph checks a corpus, or hunts, or shrinks: one of them");
  }
  options.check.validate();
  const agents::AgentConfig& agent = configAgent(config, options.check.agent);
  if (!agents::isPlanner(agent)) agents::refuseContinuous(agent, config.episode);  // planners check in both models
}

}  // namespace

void GraphOptions::validate(const ExperimentConfig& config) const {
  if (config_path.empty() || config_path[0] != '/') throw InvalidArgument("config", "expected an absolute path");
  if (output_dir.empty() || output_dir[0] != '/') throw InvalidArgument("output_dir", "expected an absolute path");
  simulator.validate();
  if (processes != agents::kProcessManager && processes != agents::kProcessOwn) {
    throw InvalidArgument("processes", "expected " + std::string(agents::kProcessManager) + " or " +
                                           agents::kProcessOwn + ", got '" + processes + "'");
  }
  bool remote = false;
  for (const agents::AgentConfig& agent : config.agents) remote = remote || !agent.host.empty();
  if (remote && (env_loader.empty() || env_loader[0] != '/')) {
    throw InvalidArgument("env_loader", "agents on other hosts need the absolute path of the workspace's env.sh");
  }
}

void assignPlanners(ExperimentConfig* config, const std::vector<std::string>& assignments) {
  for (const std::string& text : assignments) {
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw InvalidArgument("planner", "expected NAME=PACKAGE/EXECUTABLE or NAME=, got '" + text + "'");
    }
    const std::string agent = text.substr(0, equals);
    std::vector<std::string> planners;
    agents::AgentConfig* assigned = nullptr;
    for (agents::AgentConfig& a : config->agents) {
      if (!agents::isPlanner(a)) continue;
      if (a.name == agent) assigned = &a;
      planners.push_back(a.name);
    }
    if (!assigned) {
      throw InvalidArgument("planner", "the config has no planner agent named '" + agent + "' (its planner agents: " +
                                           (planners.empty() ? "none" : joinNames(planners)) + ")");
    }
    assigned->planner_node = text.substr(equals + 1);
  }
  config->validate();
}

ExperimentConfig launchedConfig(const SimulatorTask& task) {
  ExperimentConfig config = loadExperimentConfig(task.config);
  assignPlanners(&config, task.planners);
  return config;
}

std::string generatorNodeName(const std::string& set_name) {
  return ppp_msgs::nodes::kGeneratorPrefix + agents::agentGraphName(set_name);
}

std::string setTopic(const std::string& set_name) {
  return ppp_msgs::topics::under(generatorNodeName(set_name), ppp_msgs::topics::kProblemSet);
}

ppp_msgs::LaunchGraph experimentGraph(const ExperimentConfig& config, const GraphOptions& options) {
  config.validate();
  options.validate(config);
  for (const agents::AgentConfig& agent : config.agents) {
    if (playsOnSimulatedTime(agent, config.episode) && !agent.bridge.lockstep) {
      throw InvalidArgument("lockstep", "planner agent '" + agent.name + "' plays in " + kMotionContinuous +
                                            " motion, which its bridge plays in lockstep only: give it lockstep: true");
    }
  }
  const bool shrink = !options.shrink.input.empty();
  if (shrink) checkShrink(config, options);
  const bool check = !options.check.corpus.empty();
  if (check) checkCheck(config, options);
  const SetSpec* hunted = options.hunt.empty() ? nullptr : &huntedSet(config, options.hunt);
  ppp_msgs::LaunchGraph graph;
  graph.comment = "The ROS graph of " +
                  (hunted   ? "the hunt of set " + hunted->name + " of "
                   : shrink ? "the shrink of " + options.shrink.input + " for agent " + options.shrink.agent + " of "
                   : check  ? "the check of " + options.check.corpus + " for agent " + options.check.agent + " of "
                            : std::string()) +
                  "the experiment " + options.config_path + ", written by `ppp launch-file`.";
  std::vector<agents::AgentConfig> agents;
  for (const agents::AgentConfig& agent : config.agents) {
    const std::vector<std::string>* panel = hunted ? &hunted->generator->agents : nullptr;
    const bool played = shrink  ? agent.name == options.shrink.agent
                        : check ? agent.name == options.check.agent
                                : !panel || std::find(panel->begin(), panel->end(), agent.name) != panel->end();
    if (played) agents.push_back(agent);
  }
  std::set<std::string> hosts;
  for (const agents::AgentConfig& agent : agents) {
    if (agent.host.empty() || !hosts.insert(agent.host).second) continue;
    graph.machines.push_back({machineName(agent.host), agent.host, options.env_loader});
  }
  const std::string manager = options.processes == agents::kProcessManager ? ppp_msgs::nodes::kManager : "";
  if (shrink) {
    graph.nodes.push_back(shrinkNode(options.shrink));
  } else if (check) {
    graph.nodes.push_back(checkNode(options.check));
  } else if (hunted) {
    graph.nodes.push_back(generatorNode(config, *hunted, options.output_dir, options.output_dir, true));
    loadInto(manager, "ppp_generator/Generator", &graph.nodes.back());
  } else {
    for (const SetSpec& set : config.sets) {
      if (set.generator) {
        const std::string set_dir = setDirectory(set, options.output_dir);
        graph.nodes.push_back(generatorNode(config, set, options.output_dir, set_dir, false));
        loadInto(manager, "ppp_generator/Generator", &graph.nodes.back());
      }
    }
  }
  ppp_msgs::GraphNode simulator{"ppp_simulator", "simulator_node", ppp_msgs::nodes::kSimulator};
  loadInto(manager, "ppp_simulator/Simulator", &simulator);
  const bool serving = hunted || shrink || check;  // the simulator serves ~evaluate; the graph ends with its client
  simulator.required = !serving;
  SimulatorTask task;
  task.mode = serving ? kHuntMode : kExperimentMode;
  task.config = options.config_path;
  task.output_dir = serving ? "" : options.output_dir;
  task.generator_nodes = !serving;
  task.planners = options.planners;
  addParams(simulatorTaskSpecs(), task, &simulator);
  // A bridge connects to the simulator once its planner is there: the simulator waits as long as the bridges do,
  // so a planner started late costs no run (a step's timeout would fail it).
  SimulatorOptions simulator_options = options.simulator;
  for (const agents::AgentConfig& agent : agents) {
    if (!agents::isPlanner(agent)) continue;
    simulator_options.connect_timeout =
        std::max(simulator_options.connect_timeout, plannerConnectTimeout(agent) + kBridgeConnectMargin);
  }
  addParams(simulatorOptionSpecs(), simulator_options, &simulator);
  graph.nodes.push_back(simulator);
  for (const agents::AgentConfig& agent : agents) {
    if (agents::isPlanner(agent)) {
      for (ppp_msgs::GraphNode& node : plannerNodes(agent, config.episode, manager)) graph.nodes.push_back(node);
    } else {
      for (ppp_msgs::GraphNode& node : agentNodes(agent, config.episode, manager)) graph.nodes.push_back(node);
    }
  }
  if (!manager.empty()) addManager(&graph);
  // Planners in continuous motion run on simulated time: /use_sim_time is set for the whole graph, each such
  // planner reads the clock its bridge publishes (its /clock is remapped to it), and every other node is remapped
  // to a parameter nobody sets, so it keeps the system's time (its stamps and timeouts).
  if (std::any_of(agents.begin(), agents.end(),
                  [&](const agents::AgentConfig& a) { return playsOnSimulatedTime(a, config.episode); })) {
    graph.params.push_back({"/use_sim_time", "bool", "true"});
    for (ppp_msgs::GraphNode& node : graph.nodes) {
      const bool clocked = std::any_of(node.remaps.begin(), node.remaps.end(),
                                       [](const ppp_msgs::GraphRemap& r) { return r.from == kClock; });
      if (!clocked) node.remaps.push_back({"/use_sim_time", kSystemTimeParameter});
    }
  }
  return graph;
}

}  // namespace simulator
}  // namespace ppp
