#include "ppp_agents/agent_config.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <map>
#include <sstream>
#include <thread>

#include "ppp_agents/agent_registry.hpp"
#include "ppp_agents/continuous/continuous_agent.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/motion_options.hpp"
#include "ppp_core/option_yaml.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {
namespace agents {

namespace {

/// Largest memory window side: centred anywhere on the largest map, it covers the whole map.
constexpr int kMaxMemoryWindow = 2 * kMaxGridSide - 1;

/// What is wrong with asking for a prior map, or "" when nothing is.
std::string priorMapProblem(const AgentConfig& config) {
  if (!config.prior_map || config.type == kPlannerType) return "";
  return "only planner agents take prior_map (astar always has the map; the other agents never do)";
}

/// What is wrong with the goal seeking asked for, or "" when nothing is.
std::string goalSeekingProblem(const AgentConfig& config) {
  if (config.goal_seeking == kGoalSeekingByType) return "";
  if (agentType(config.type).has(AgentTrait::NeedsPriorMap)) {
    return config.type + " plans its route to the goal from the start; goal seeking does not apply";
  }
  if (config.type == kPlannerType) return "a planner agent's planner is given the goal; goal seeking does not apply";
  return "";
}

/// What is wrong with the goal range asked for, or "" when nothing is.
std::string goalRangeProblem(const AgentConfig& config) {
  if (config.goal_range == 0 || seeksGoal(config)) return "";
  AgentConfig seeking = config;
  seeking.goal_seeking = kGoalSeekingOn;
  const std::string remedy = goalSeekingProblem(seeking).empty() ? "; goal_seeking: on makes it one" : "";
  return "only agents that head for the goal once they notice it take it (this one's goal_seeking is '" +
         config.goal_seeking + "', type " + config.type + remedy + ")";
}

/// What is wrong with the wall sense asked for, or "" when nothing is.
std::string wallSenseProblem(const AgentConfig& config) {
  if (config.wall_sense != kWallSenseTouch || config.wall_leave != kWallLeaveGoalFree) return "";
  return "a wall follower by touch cannot let go when the way to the goal is free (wall_leave: goal_free): it "
         "does not see it";
}

/// What is wrong with the memory model asked for, or "" when nothing is.
std::string memoryModelProblem(const AgentConfig& config) {
  if (config.memory_model == kMemoryModelWindow || config.type != kPlannerType) return "";
  return "a planner agent's memory is a window (the bridge's)";
}

/// An option only one kind of built-in agent takes (its types have `trait`); any other agent must leave it at its
/// default.
struct KindOption {
  const char* key;     ///< The option.
  AgentTrait trait;    ///< What the types that take it have.
  const char* takers;  ///< Those types, as errors name them.
};

/// Every option of one kind of agent, in the order validate() checks them.
const std::vector<KindOption>& kindOptions() {
  static const std::vector<KindOption> options = {
      {"wall_start", AgentTrait::FollowsWalls, "wall followers"},
      {"wall_leave", AgentTrait::FollowsWalls, "wall followers"},
      {"goal_ties", AgentTrait::FollowsWalls, "wall followers"},
      {"wall_sense", AgentTrait::FollowsWalls, "wall followers"},
      {"bumper_turn", AgentTrait::Bumps, "bumpers"},
      {"explorer_idle", AgentTrait::Explores, "explorers"},
      {"explorer_ties", AgentTrait::Explores, "explorers"},
      {"frontier", AgentTrait::SeeksFrontiers, "long-term explorers"},
  };
  return options;
}

/// The options that decide how one run plays: the play flags, and with "name" the agent node's parameters.
std::vector<std::string> playOptionNames() {
  std::vector<std::string> names = {"type", "memory", "sensor_noise", "goal_seeking", "goal_range", "memory_model"};
  for (const KindOption& option : kindOptions()) names.push_back(option.key);
  return names;
}

/// @throws InvalidArgument naming the first option of another kind of agent that `config` sets off its default.
void checkKindOptions(const AgentConfig& config) {
  static const AgentConfig defaults;
  for (const KindOption& option : kindOptions()) {
    const OptionSpec<AgentConfig>& spec = optionNamed(agentOptionSpecs(), option.key);
    if (!agentType(config.type).has(option.trait) && spec.text(config) != spec.text(defaults)) {
      throw InvalidArgument(option.key, std::string("only ") + option.takers + " take it");
    }
  }
}

/// What is wrong with the plan request rule asked for, or "" when nothing is.
std::string agentPlanRequestsProblem(const AgentConfig& config) {
  if (config.type == kPlannerType || asksEveryStep(config.bridge)) return planRequestsProblem(config.bridge);
  return "only planner agents ask a planner for plans";
}

/// What is wrong with the planner interface asked for, or "" when nothing is.
std::string agentInterfaceProblem(const AgentConfig& config) {
  if (config.type == kPlannerType) return interfaceProblem(config.bridge);
  if (commandsVelocity(config.bridge)) return "only planner agents answer through a planner interface";
  return "";
}

/// What is wrong with the instances asked for, or "" when nothing is.
std::string instancesProblem(const AgentConfig& config) {
  if (config.instances == 0 || config.type == kPlannerType || movesContinuously(config)) return "";
  return "only planner agents, and astar in continuous motion, run as several instances (the other agents' nodes "
         "play batches of runs)";
}

/// Whether `name` is a legal ROS package or executable name: letters, digits, '_', '-' and '.', not empty.
bool isFileName(const std::string& name) {
  if (name.empty() || name[0] == '.') return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '.';
  });
}

/// What is wrong with a planner node "package/executable", or "" when nothing is.
std::string plannerNodeProblem(const AgentConfig& config) {
  if (config.planner_node.empty()) return "";
  if (config.type != kPlannerType) return "only planner agents start a planner node";
  const std::size_t slash = config.planner_node.find('/');
  if (slash == std::string::npos || !isFileName(config.planner_node.substr(0, slash)) ||
      !isFileName(config.planner_node.substr(slash + 1))) {
    return "expected package/executable (e.g. ppp_agents/ompl_planner_node), got '" + config.planner_node + "'";
  }
  return "";
}

/// What is wrong with a planner node's arguments, or "" when nothing is: each word a private parameter
/// `_name:=value` (what ros::init reads as ~name), given only with the planner_node they are for.
std::string plannerArgsProblem(const AgentConfig& config) {
  if (config.planner_args.empty()) return "";
  if (config.planner_node.empty()) return "given to the planner_node the experiment starts; this agent has none";
  std::istringstream words(config.planner_args);
  for (std::string word; words >> word;) {
    const std::size_t assign = word.find(":=");
    const bool named = word[0] == '_' && assign != std::string::npos && assign > 1 &&
                       std::all_of(word.begin() + 1, word.begin() + static_cast<long>(assign), [](char c) {
                         return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '/';
                       });
    const bool plain = word.find_first_of("\"'<>&") == std::string::npos;
    if (!named || !plain) {
      return "expected private parameters _name:=value separated by spaces (e.g. _planning_time:=0.005), got '" +
             word + "'";
    }
  }
  return "";
}

/// What is wrong with a host name or address, or "" when nothing is.
std::string hostProblem(const std::string& host) {
  const bool legal = std::all_of(host.begin(), host.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '.' || c == '-' || c == ':' || c == '_';
  });
  if (legal && host.size() <= 253) return "";
  return "expected a host name or IP address (letters, digits, '.', '-', ':'), got '" + host + "'";
}

/// Parses a whole string of decimal digits; false on anything else or overflow.
bool parseSide(const std::string& text, int* value) {
  if (text.empty() || text[0] == '-' || text[0] == '+') return false;
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, *value);
  return result.ec == std::errc() && result.ptr == end;
}

/// Parses "KxK" or "full" into `window`; returns what is wrong, or "" when nothing is.
std::string memoryWindowProblem(const std::string& text, int* window) {
  if (text == "full") {
    *window = 0;
    return "";
  }
  const std::size_t x = text.find('x');
  int width = 0;
  int height = 0;
  if (x == std::string::npos || !parseSide(text.substr(0, x), &width) || !parseSide(text.substr(x + 1), &height)) {
    return "expected KxK with odd K (e.g. 5x5) or 'full', got '" + text + "'";
  }
  if (width != height) return "the window must be square (KxK), got '" + text + "'";
  if (width < 1 || width % 2 == 0 || width > kMaxMemoryWindow) {
    return "the window side must be odd and in [1, " + std::to_string(kMaxMemoryWindow) +
           "] (the window is centred on the agent), got '" + text + "'";
  }
  *window = width;
  return "";
}

}  // namespace

void AgentConfig::validate() const {
  agentType(type);
  if (name.empty()) throw InvalidArgument("name", "expected a non-empty agent name");
  checkOptionRanges(agentOptionSpecs(), *this);
  if (memory_window != 0 && (memory_window < 1 || memory_window % 2 == 0 || memory_window > kMaxMemoryWindow)) {
    throw InvalidArgument("memory", "expected an odd window side in [1, " + std::to_string(kMaxMemoryWindow) +
                                        "] (5 for 5x5) or 0 for full memory, got " + std::to_string(memory_window));
  }
  if (!goalSeekingProblem(*this).empty()) throw InvalidArgument("goal_seeking", goalSeekingProblem(*this));
  if (!goalRangeProblem(*this).empty()) throw InvalidArgument("goal_range", goalRangeProblem(*this));
  if (!memoryModelProblem(*this).empty()) throw InvalidArgument("memory_model", memoryModelProblem(*this));
  checkKindOptions(*this);
  if (!wallSenseProblem(*this).empty()) throw InvalidArgument("wall_sense", wallSenseProblem(*this));
  if (!priorMapProblem(*this).empty()) throw InvalidArgument("prior_map", priorMapProblem(*this));
  if (!plannerNodeProblem(*this).empty()) throw InvalidArgument("planner_node", plannerNodeProblem(*this));
  if (!plannerArgsProblem(*this).empty()) throw InvalidArgument("planner_args", plannerArgsProblem(*this));
  if (!instancesProblem(*this).empty()) throw InvalidArgument("instances", instancesProblem(*this));
  if (!agentPlanRequestsProblem(*this).empty()) {
    throw InvalidArgument("plan_requests", agentPlanRequestsProblem(*this));
  }
  if (!agentInterfaceProblem(*this).empty()) throw InvalidArgument("interface", agentInterfaceProblem(*this));
  const std::string period_messages = periodMessagesProblem(plannerBridgeOptions(*this));
  if (!period_messages.empty()) throw InvalidArgument("period_messages", period_messages);
  if (!hostProblem(host).empty()) throw InvalidArgument("host", hostProblem(host));
}

const std::vector<OptionSpec<AgentConfig>>& agentOptionSpecs() {
  using A = AgentConfig;
  static const std::vector<OptionSpec<A>> specs = [] {
    std::vector<OptionSpec<A>> list = {
        declareOption("type", "agent type: " + agentTypeList(), +[](A& a) -> std::string& { return a.type; }),
        declareOption("name", "name in results and reports (default: the type)",
                      +[](A& a) -> std::string& { return a.name; }),
        declareTextOption("memory", "a memory window KxK (odd K) or 'full'",
                          "limited memory: keep only a KxK window around the agent",
                          +[](A& a) -> int& { return a.memory_window; }, &memoryWindowProblem, &memoryWindowText,
                          {"full", "5x5", "3x3"}),
        declareOption("sensor_noise", "probability that a sensed cell is reported flipped",
                      +[](A& a) -> double& { return a.sensor_noise; }, Bounds{0, 1}),
        declareOption("goal_seeking", "what the agent does once it has seen the goal",
                      +[](A& a) -> std::string& { return a.goal_seeking; })
            .withChoices("goal seeking",
                         {{kGoalSeekingByType, "as its type's design: every type but random heads for it"},
                          {kGoalSeekingOn, "it takes a shortest path to the goal on its memory"},
                          {kGoalSeekingOff, "it plays its strategy as if it had not seen it"}}),
        declareOption("goal_range",
                      "goal seekers: how near the goal must be for the agent to notice it: within this many cells "
                      "(Chebyshev distance), whatever lies between, as a robot that knows both positions, besides "
                      "when its scan shows the goal free (in the window, in line of sight); 0: only then",
                      +[](A& a) -> int& { return a.goal_range; }, Bounds{0, kMaxGridSide}),
        declareOption("memory_model", "what a limited memory KxK keeps",
                      +[](A& a) -> std::string& { return a.memory_model; })
            .withChoices("memory model",
                         {{kMemoryModelWindow, "the KxK cells around the agent"},
                          {kMemoryModelScans, "what its last K x K scans saw, older sightings forgotten"}}),
        declareOption("wall_start", "wall followers: what they do before touching a wall",
                      +[](A& a) -> std::string& { return a.wall_start; })
            .withChoices("wall start", {{kWallStartGoal, "head for the goal"},
                                        {kWallStartRandom, "go straight on in a heading drawn at random"}}),
        declareOption("wall_leave", "wall followers: when they let go of the wall they follow",
                      +[](A& a) -> std::string& { return a.wall_leave; })
            .withChoices("wall leave",
                         {{kWallLeaveNever, "the first wall touched is followed for good"},
                          {kWallLeaveGoalFree,
                           "as soon as the move towards the goal is free (Bug0), then head for the goal until the "
                           "next wall"}}),
        declareOption("goal_ties", "wall followers heading for the goal: their move when it is as far across as down",
                      +[](A& a) -> std::string& { return a.goal_ties; })
            .withChoices("goal ties", {{kGoalTiesHorizontal, "across (East or West)"},
                                       {kGoalTiesRandom, "across or down, drawn at random each time"}}),
        declareOption("wall_sense", "wall followers: how they find the wall they follow",
                      +[](A& a) -> std::string& { return a.wall_sense; })
            .withChoices("wall sense",
                         {{kWallSenseScan, "from the scan (the four neighbours it reports)"},
                          {kWallSenseTouch,
                           "by touch: each step it tries its moves in the hand-on-wall order, from the one towards "
                           "the wall, and takes the first that does not bump (each bump is an action)"}}),
        declareOption("bumper_turn", "bumpers: the directions they draw a new one from after a bump",
                      +[](A& a) -> std::string& { return a.bumper_turn; })
            .withChoices("bumper turn", {{kBumperTurnOther, "the three other than the one that bumped"},
                                         {kBumperTurnQuarter, "a quarter turn, left or right, never straight back"}}),
        declareOption("explorer_idle", "explorers: where they move when no neighbour would reveal anything",
                      +[](A& a) -> std::string& { return a.explorer_idle; })
            .withChoices("explorer idle",
                         {{kExplorerIdleRandom, "to a random free neighbour"},
                          {kExplorerIdleLeastVisited, "to the free neighbour stood on least often, ties at random"}}),
        declareOption("explorer_ties", "explorers: which of the neighbours revealing most unknown cells they move to",
                      +[](A& a) -> std::string& { return a.explorer_ties; })
            .withChoices("explorer ties",
                         {{kExplorerTiesRandom, "one at random"},
                          {kExplorerTiesGoal, "one of those nearest the goal (Manhattan distance), then at random"}}),
        declareOption("frontier", "long-term explorers: the frontier they walk to when nothing new is in reach",
                      +[](A& a) -> std::string& { return a.frontier; })
            .withChoices("frontier",
                         {{kFrontierNearest, "the nearest (the shortest walk on known-free cells)"},
                          {kFrontierGoal,
                           "the one with the least walk to it plus Manhattan distance on to the goal (goal-directed "
                           "exploration), the nearer on ties"}}),
        declareOption("runs", "runs per PPP for this agent (0: the experiment's runs)",
                      +[](A& a) -> int& { return a.runs; }, Bounds{0, kMaxRuns}),
        declareOption("prior_map", "planner agents: the planner is given the true map instead of the memory",
                      +[](A& a) -> bool& { return a.prior_map; }),
        declareOption("planner_node", "planner agents: package/executable of the planner to start",
                      +[](A& a) -> std::string& { return a.planner_node; }),
        declareOption("planner_args",
                      "planner agents: private parameters of the planner_node, as _name:=value words (e.g. "
                      "_planning_time:=0.005)",
                      +[](A& a) -> std::string& { return a.planner_args; }),
        declareOption("instances",
                      "planner agents and astar in continuous motion, through ROS: bridge and planner pairs, or "
                      "agent nodes, playing its runs in parallel, results identical whatever their number (0: this "
                      "machine's cores when the experiment starts the planner or in continuous motion, else 1)",
                      +[](A& a) -> int& { return a.instances; }, Bounds{0, kMaxInstances})
            .notAffectingResults(),
        declareOption("host", "through ROS: the machine the agent's nodes run on ('': the simulator's)",
                      +[](A& a) -> std::string& { return a.host; })
            .notAffectingResults(),
        declareOption("process", "through ROS: where a built-in agent's node runs",
                      +[](A& a) -> std::string& { return a.process; })
            .withChoices("process",
                         {{kProcessManager,
                           "in the experiment's nodelet manager, beside the simulator (batches handed over without "
                           "a copy); an agent on another host runs in a process of its own there"},
                          {kProcessOwn, "in a process of its own (an agent that may crash takes nothing else down)"}})
            .notAffectingResults(),
        declareOption("motion", "how this agent's robot moves", +[](A& a) -> std::string& { return a.motion; })
            .withChoices("motion", {{kMotionOfExperiment, "as the experiment's motion option says"},
                                          {kMotionGrid, "one cell per action"},
                                          {kMotionContinuous, "velocity, heading and a 2D laser (astar, planners)"}}),
    };
    const std::vector<OptionSpec<BridgeOptions>> per_agent =
        selectOptions(bridgeOptionSpecs(), {"plan_timeout", "lockstep", "plan_requests", "interface", "endless_proof",
                                            "wakes_on", "period_messages", "cells_per_ppp_cell"});
    for (OptionSpec<A>& spec : nestedOptions(per_agent, +[](A& a) -> BridgeOptions& { return a.bridge; })) {
      spec.doc = "planner agents: " + spec.doc;
      list.insert(list.end() - 2, spec);  // before host and process
    }
    list[0].flag = "agent";
    return list;
  }();
  return specs;
}

namespace {

/// The options `names` of agentOptionSpecs() (the first "type"), for a source that plays built-in agents only:
/// its type's doc lists the types it accepts.
std::vector<OptionSpec<AgentConfig>> builtInAgentOptions(const std::vector<std::string>& names) {
  std::vector<OptionSpec<AgentConfig>> specs = selectOptions(agentOptionSpecs(), names);
  specs[0].doc = "agent type: " + joinNames(agentTypeNames()) + " (" + kPlannerType +
                 " agents play only through ROS, in an experiment or a hunt)";
  return specs;
}

}  // namespace

const std::vector<OptionSpec<AgentConfig>>& agentNodeOptionSpecs() {
  static const std::vector<OptionSpec<AgentConfig>> specs = [] {
    std::vector<std::string> names = playOptionNames();
    names.insert(names.begin() + 1, "name");
    return builtInAgentOptions(names);
  }();
  return specs;
}

const std::vector<OptionSpec<AgentConfig>>& agentPlayOptionSpecs() {
  static const std::vector<OptionSpec<AgentConfig>> specs = builtInAgentOptions(playOptionNames());
  return specs;
}

std::string replayFlags(const AgentConfig& config, const EpisodeOptions& episode) {
  std::string flags = optionFlags(agentPlayOptionSpecs(), config, AgentConfig{});
  const std::string episode_flags = optionFlags(episodeOptionSpecs(), episode, EpisodeOptions{});
  return episode_flags.empty() ? flags : flags + " " + episode_flags;
}

std::string replayCommand(const std::string& file, const std::string& flags, std::uint64_t seed) {
  return "ppp replay " + shellWord(file) + " " + flags + " --seed " + std::to_string(seed) + " -o path.png";
}

std::string replayCommand(const std::string& file, const AgentConfig& config, const EpisodeOptions& episode,
                          std::uint64_t seed) {
  return replayCommand(file, replayFlags(config, episode), seed);
}

bool isPlanner(const AgentConfig& config) { return config.type == kPlannerType; }

bool playsContinuously(const AgentConfig& config, const EpisodeOptions& options) {
  return (config.motion == kMotionOfExperiment ? options.motion.motion : config.motion) == kMotionContinuous;
}

const ExamplePlanner* examplePlanner(const std::string& planner_node) {
  static const std::map<std::string, ExamplePlanner> planners = {
      {"ppp_agents/optimistic_planner_node", {"ppp_agents/OptimisticPlanner", false}},
      {"ppp_agents/zoo_planner_node", {"ppp_agents/ZooPlanner", false}},
      {"ppp_agents/ompl_planner_node", {"ppp_agents/OmplPlanner", false}},
      {"ppp_agents/mrpt_planner_node", {"ppp_agents/MrptPlanner", false}},
      {"ppp_agents/mrpt_reactive_node", {"ppp_agents/MrptReactive", true}},
      {"ppp_agents/dwa_planner_node", {"ppp_agents/DwaPlanner", true}},
      {"ppp_agents/mrpt_tpspace_node", {nullptr, true}},
      {"ppp_agents/echo_planner_node", {"ppp_agents/EchoPlanner", true}}};
  const auto found = planners.find(planner_node);
  return found != planners.end() ? &found->second : nullptr;
}

std::string plannerWakesOn(const AgentConfig& config) {
  if (config.bridge.wakes_on != kWakesOnAuto) return config.bridge.wakes_on;
  const ExamplePlanner* planner = examplePlanner(config.planner_node);
  return planner != nullptr && planner->answers_messages ? kWakesOnMessages : kWakesOnTimer;
}


std::string plannerPeriodMessages(const AgentConfig& config) {
  if (config.bridge.period_messages != kPeriodMessagesAuto) return config.bridge.period_messages;
  const ExamplePlanner* planner = examplePlanner(config.planner_node);
  const bool ours = planner != nullptr && planner->answers_messages;
  return ours && plannerWakesOn(config) == kWakesOnMessages ? kPeriodMessagesChanges : kPeriodMessagesEvery;
}

BridgeOptions plannerBridgeOptions(const AgentConfig& config) {
  BridgeOptions options = config.bridge;
  options.wakes_on = plannerWakesOn(config);
  options.period_messages = plannerPeriodMessages(config);
  return options;
}

int instanceCount(const AgentConfig& config, const EpisodeOptions& options) {
  const bool planner = isPlanner(config);
  if (!planner && !playsContinuously(config, options)) return 1;
  if (config.instances > 0) return config.instances;
  if (planner && config.planner_node.empty()) return 1;
  return std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, kMaxInstances);
}

std::string instanceGraphName(const AgentConfig& config, int instance, int instances) {
  const std::string name = agentGraphName(config.name);
  return instances == 1 ? name : name + "/instance_" + std::to_string(instance + 1);
}

const std::vector<std::string>& agentTypeNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> built_in;
    for (const AgentType& type : agentRegistry()) {
      if (type.make != nullptr) built_in.push_back(type.name);
    }
    return built_in;
  }();
  return names;
}

std::string memoryWindowText(int window) {
  return window == 0 ? std::string("full") : std::to_string(window) + "x" + std::to_string(window);
}

std::vector<AgentConfig> readAgentConfigs(YamlMapReader& reader, const std::string& key) {
  const YAML::Node list = reader.lookup(key);
  if (!list) throw ParseError(reader.source(), 0, reader.fieldName(key), "missing; expected a list of agents");
  if (!list.IsSequence()) reader.fail(list, key, "expected a list of agents, each a mapping with a type");
  if (list.size() == 0) reader.fail(list, key, "expected at least one agent");
  std::vector<AgentConfig> configs;
  std::map<std::string, std::size_t> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const YAML::Node node = list[i];
    YamlMapReader item(node, reader.source(), reader.fieldName(key) + "[" + std::to_string(i) + "]");
    AgentConfig config;
    readOptionsYaml(item, agentOptionSpecs(), &config);
    item.rejectUnknownKeys();
    if (!item.lookup("type")) item.fail(node, "type", "missing; valid: " + agentTypeList());
    if (!item.lookup("name")) config.name = config.type;
    try {
      config.validate();
    } catch (const InvalidArgument& e) {
      const YAML::Node at = item.lookup(e.name());
      item.fail(at ? at : node, e.name(), e.problem());
    }
    const auto inserted = names.emplace(config.name, i);
    if (!inserted.second) {
      item.fail(item.lookup("name") ? item.lookup("name") : node, "name",
                "duplicate agent name '" + config.name + "' (also " + reader.fieldName(key) + "[" +
                    std::to_string(inserted.first->second) + "]); give each configuration its own name");
    }
    configs.push_back(config);
  }
  return configs;
}

std::vector<AgentConfig> loadAgentConfigs(const std::string& path) {
  const YAML::Node root = loadYamlFile(path);
  YamlMapReader reader(root, path);
  std::vector<AgentConfig> configs = readAgentConfigs(reader, "agents");
  reader.rejectUnknownKeys();
  return configs;
}

std::string agentGraphName(const std::string& name) {
  const auto is_letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
  std::string graph_name = name.empty() || !is_letter(name[0]) ? "agent_" + name : name;
  for (char& c : graph_name) {
    if (!is_letter(c) && !(c >= '0' && c <= '9')) c = '_';
  }
  return graph_name;
}

}  // namespace agents
}  // namespace ppp
