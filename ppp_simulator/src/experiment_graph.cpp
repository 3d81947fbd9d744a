#include "ppp_simulator/experiment_graph.hpp"

#include <algorithm>
#include <set>
#include <sstream>

#include "ppp_core/error.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_generator/fitness.hpp"
#include "ppp_generator/generator_node_options.hpp"
#include "ppp_msgs/topic_names.h"

namespace ppp {
namespace simulator {

namespace {

/// `text` as a double-quoted XML attribute value; line breaks survive as character references.
/// @throws InvalidArgument naming `what` for text roslaunch would substitute ("$(").
std::string attribute(const std::string& text, const std::string& what) {
  if (text.find("$(") != std::string::npos) {
    throw InvalidArgument(what, "must not contain \"$(\" (roslaunch would substitute it): " + text);
  }
  std::string out;
  for (const char c : escapeMarkup(text)) {
    if (c == '\n') {
      out += "&#10;";
    } else if (c == '\t') {
      out += "&#9;";
    } else if (c == '\r') {
      out += "&#13;";
    } else {
      out += c;
    }
  }
  return "\"" + out + "\"";
}

/// `<param name="NAME" type="TYPE" value="VALUE"/>`.
std::string param(const std::string& name, const std::string& type, const std::string& value) {
  return "<param name=\"" + name + "\" type=\"" + type + "\" value=" + attribute(value, "~" + name) + "/>";
}

/// The roslaunch param type of a declared option ("int", "double", "bool"; else "str").
template <typename Options>
std::string parameterType(const OptionSpec<Options>& spec) {
  switch (spec.kind) {
    case OptionKind::Integer: return "int";
    case OptionKind::Number: return "double";
    case OptionKind::Boolean: return "bool";
    default: return "str";
  }
}

/// One `<param>` line per declared option of `specs`, with its value in `values` (strings unquoted).
template <typename Options>
std::string params(const std::vector<OptionSpec<Options>>& specs, const Options& values, const std::string& indent) {
  std::string lines;
  for (const OptionSpec<Options>& spec : specs) {
    lines += indent + param(spec.name, parameterType(spec), spec.plainText(values)) + "\n";
  }
  return lines;
}

/// `<remap from="TOPIC" to="~TOPIC"/>`: the node's topic under its own name.
std::string privateTopic(const char* topic) {
  return std::string("<remap from=\"") + topic + "\" to=\"~" + topic + "\"/>";
}

/// The machine name of a host.
std::string machineName(const std::string& host) { return "host_" + agents::agentGraphName(host); }

/// ` machine="..."` for an agent on another host, or "".
std::string machineOf(const agents::AgentConfig& agent) {
  return agent.host.empty() ? "" : " machine=" + attribute(machineName(agent.host), "host");
}

/// A generator node for `set` writing `output_dir`; a hunt's is required and exits when its set is written.
void writeGenerator(std::ostream& out, const SetSpec& set, const std::string& output_dir, bool hunt) {
  generator::GeneratorNodeOptions node;
  node.options_yaml = generator::generatorOptionsYaml(*set.generator);
  node.set_name = set.name;
  node.output_dir = output_dir;
  node.resume = true;
  node.exit_when_done = hunt;
  out << "  <node pkg=\"ppp_generator\" type=\"generator_node\" name=" << attribute(generatorNodeName(set.name), "sets")
      << " output=\"screen\"" << (hunt ? " required=\"true\"" : "") << ">\n"
      << params(generator::generatorNodeOptionSpecs(), node, "    ")
      << "    " << privateTopic(ppp_msgs::topics::kProblemSet) << "\n"
      << "    " << privateTopic(ppp_msgs::topics::kMap) << "\n"
      << "  </node>\n";
}

void writeAgent(std::ostream& out, const agents::AgentConfig& agent) {
  out << "  <node pkg=\"ppp_agents\" type=\"agent_node\" name=" << attribute(agents::agentGraphName(agent.name), "name")
      << machineOf(agent) << " output=\"screen\">\n"
      << params(agents::agentNodeOptionSpecs(), agent, "    ")
      << "    " << privateTopic(ppp_msgs::topics::kScans) << "\n"
      << "    " << privateTopic(ppp_msgs::topics::kMoves) << "\n"
      << "  </node>\n";
}

void writePlanner(std::ostream& out, const agents::AgentConfig& agent) {
  const std::size_t slash = agent.planner_node.find('/');
  const std::string package = agent.planner_node.substr(0, slash);
  const std::string type = slash == std::string::npos ? "" : agent.planner_node.substr(slash + 1);
  out << "  <group ns=" << attribute(agents::agentGraphName(agent.name), "name") << ">\n"
      << "    <node pkg=\"ppp_agents\" type=\"planner_bridge_node\" name=\"bridge\"" << machineOf(agent)
      << " output=\"screen\">\n"
      << "      " << param("memory", "str", agents::memoryWindowText(agent.memory_window)) << "\n"
      // A planner the user starts by hand gets five minutes to appear; one started here, 20 s.
      << "      " << param("connect_timeout", "double", type.empty() ? "300.0" : "20.0") << "\n"
      << "    </node>\n";
  if (!type.empty()) {
    out << "    <node pkg=" << attribute(package, "planner_node") << " type=" << attribute(type, "planner_node")
        << " name=\"planner\" ns=\"" << ppp_msgs::topics::kRobotNamespace << "\"" << machineOf(agent) << " output=\"screen\"/>\n";
  }
  out << "  </group>\n";
}

/// The set a hunt graph evolves. @throws InvalidArgument naming "hunt" unless it is a `failure` set of `config`.
const SetSpec& huntedSet(const ExperimentConfig& config, const std::string& name) {
  std::vector<std::string> hunted;
  for (const SetSpec& set : config.sets) {
    if (!set.generator || set.generator->fitness != generator::kFailureFitness) continue;
    if (set.name == name) return set;
    hunted.push_back(set.name);
  }
  throw InvalidArgument("hunt", "the config has no set '" + name + "' evolved with the failure fitness (its hunted sets: " +
                                    (hunted.empty() ? "none" : joinNames(hunted)) + ")");
}

}  // namespace

void GraphOptions::validate(const ExperimentConfig& config) const {
  if (config_path.empty() || config_path[0] != '/') throw InvalidArgument("config", "expected an absolute path");
  if (output_dir.empty() || output_dir[0] != '/') throw InvalidArgument("output_dir", "expected an absolute path");
  simulator.validate();
  bool remote = false;
  for (const agents::AgentConfig& agent : config.agents) remote = remote || !agent.host.empty();
  if (remote && (env_loader.empty() || env_loader[0] != '/')) {
    throw InvalidArgument("env_loader", "agents on other hosts need the absolute path of the workspace's env.sh");
  }
}

void assignPlannerNode(ExperimentConfig* config, const std::string& agent, const std::string& planner_node) {
  std::vector<std::string> planners;
  for (agents::AgentConfig& a : config->agents) {
    if (!agents::isPlanner(a)) continue;
    if (a.name == agent) {
      a.planner_node = planner_node;
      return;
    }
    planners.push_back(a.name);
  }
  throw InvalidArgument("planner", "the config has no planner agent named '" + agent + "' (its planner agents: " +
                                       (planners.empty() ? "none" : joinNames(planners)) + ")");
}

std::string generatorNodeName(const std::string& set_name) { return "gen_" + agents::agentGraphName(set_name); }

std::string setTopic(const std::string& set_name) {
  return ppp_msgs::topics::under(generatorNodeName(set_name), ppp_msgs::topics::kProblemSet);
}

std::string experimentLaunchXml(const ExperimentConfig& config, const GraphOptions& options) {
  config.validate();
  options.validate(config);
  const SetSpec* hunted = options.hunt.empty() ? nullptr : &huntedSet(config, options.hunt);
  std::ostringstream out;
  out << "<launch>\n"
      << "  <!-- The ROS graph of " << (hunted ? "the hunt of set " + escapeMarkup(hunted->name) + " of " : "")
      << "the experiment " << escapeMarkup(options.config_path) << ", written by `ppp launch-file`. -->\n";
  std::vector<agents::AgentConfig> agents;
  for (const agents::AgentConfig& agent : config.agents) {
    const std::vector<std::string>* panel = hunted ? &hunted->generator->agents : nullptr;
    if (!panel || std::find(panel->begin(), panel->end(), agent.name) != panel->end()) agents.push_back(agent);
  }
  std::set<std::string> hosts;
  for (const agents::AgentConfig& agent : agents) {
    if (agent.host.empty() || !hosts.insert(agent.host).second) continue;
    out << "  <machine name=" << attribute(machineName(agent.host), "host")
        << " address=" << attribute(agent.host, "host") << " env-loader=" << attribute(options.env_loader, "env_loader")
        << "/>\n";
  }
  if (hunted) {
    writeGenerator(out, *hunted, options.output_dir, true);
  } else {
    for (const SetSpec& set : config.sets) {
      if (set.generator) writeGenerator(out, set, options.output_dir + "/sets/" + set.name, false);
    }
  }
  out << "  <node pkg=\"ppp_simulator\" type=\"simulator_node\" name=\"simulator\" output=\"screen\""
      << (hunted ? "" : " required=\"true\"") << ">\n";
  SimulatorTask task;
  task.mode = hunted ? kHuntMode : kExperimentMode;
  task.config = options.config_path;
  task.output_dir = hunted ? "" : options.output_dir;
  task.generator_nodes = !hunted;
  out << params(simulatorTaskSpecs(), task, "    ") << params(simulatorOptionSpecs(), options.simulator, "    ")
      << "  </node>\n";
  for (const agents::AgentConfig& agent : agents) {
    if (agents::isPlanner(agent)) {
      writePlanner(out, agent);
    } else {
      writeAgent(out, agent);
    }
  }
  out << "</launch>\n";
  return out.str();
}

}  // namespace simulator
}  // namespace ppp
