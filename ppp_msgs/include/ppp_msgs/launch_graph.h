#pragma once

#include <string>
#include <utility>
#include <vector>

// A ROS graph as a value (machines, nodes, their parameters and remappings), rendered as roslaunch XML for
// roslaunch and as JSON for the launcher's checks. ROS-free: the experiment's graph writer builds it, `ppp
// launch-file` prints it.
namespace ppp_msgs {

/// One `<param>` of a node: a private parameter with its roslaunch type.
struct GraphParam {
  std::string name;   ///< Parameter name, relative to the node ("budget", "weights/goal").
  std::string type;   ///< roslaunch type: "int", "double", "bool" or "str".
  std::string value;  ///< The value as text.
};

/// One `<remap>` of a node.
struct GraphRemap {
  std::string from;  ///< The name the node uses.
  std::string to;    ///< What it becomes ("~problem_set": under the node's own name).
};

/// One node of the graph.
struct GraphNode {
  GraphNode() = default;
  /// The node `name`, executable `type` of `package`, with nothing else set.
  GraphNode(std::string package_name, std::string executable, std::string node_name)
      : package(std::move(package_name)), type(std::move(executable)), name(std::move(node_name)) {}

  std::string package;    ///< ROS package (of the executable, or of the nodelet).
  std::string type;       ///< Executable (unused for a nodelet).
  std::string name;       ///< Node name.
  std::string group;      ///< Namespace of the `<group>` holding it ("" for none).
  std::string ns;         ///< Its own `ns` attribute inside that group ("" for none).
  std::string machine;    ///< The `<machine>` it runs on ("" for this one).
  std::string agent;      ///< The experiment's agent it serves ("" for the generators and the simulator).
  bool required = false;  ///< roslaunch stops everything when it ends.
  std::string args;       ///< Its command-line arguments ("" for none), e.g. private parameters `_name:=value`.
  std::vector<GraphParam> params;  ///< Its private parameters.
  std::vector<GraphRemap> remaps;  ///< Its remappings.
  /// The nodelet type ("ppp_agents/Agent") when the node runs as a nodelet in the manager `manager` (a node of the
  /// graph); "" for a process of its own.
  std::string nodelet;
  std::string manager;  ///< The manager's node name, for a nodelet.
};

/// One `<machine>`: another host nodes run on.
struct GraphMachine {
  std::string name;        ///< Machine name the nodes refer to.
  std::string address;     ///< Host name or address (reached over ssh).
  std::string env_loader;  ///< Script the host runs nodes through.
  /// Seconds roslaunch waits for the host's remote roslaunch to register. Its own default, 10 s, is shorter than
  /// an ssh login and a Python start take on a busy host.
  int start_timeout = 60;
};

/// A whole graph.
struct LaunchGraph {
  std::string comment;                 ///< What the graph is, one line.
  std::vector<GraphMachine> machines;  ///< Other hosts.
  std::vector<GraphParam> params;      ///< Global parameters (absolute names), set before any node starts.
  std::vector<GraphNode> nodes;        ///< Every node, in start order.
  /// The private parameter a job run as a nodelet in the required manager sets to its exit status when it is done
  /// ("/simulator/exit_status"; the manager itself exits 0), or "" when the required node is the job itself.
  std::string status_param;
};

/// The roslaunch XML of `graph`; nodes with a group are wrapped in `<group ns="...">` (consecutive nodes of one
/// group share it); a nodelet is a `nodelet load TYPE MANAGER --no-bond` node of the same name, parameters and
/// remappings (no bond: its heartbeat counts wall time and would unload nodelets of a manager slowed by load). @throws ppp::InvalidArgument naming the node for text roslaunch would substitute ("$(").
std::string launchXml(const LaunchGraph& graph);

/// `graph` as JSON: {"comment", "required": the required node's name or "", "status_param", "machines": [{"name", "address",
/// "env_loader", "agents": [names of the agents with a node there]}], "nodes": [...], "xml": launchXml(graph)}.
/// @throws ppp::InvalidArgument as launchXml().
std::string launchJson(const LaunchGraph& graph);

}  // namespace ppp_msgs
