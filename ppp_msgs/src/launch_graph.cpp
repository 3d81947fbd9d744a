#include "ppp_msgs/launch_graph.h"

#include <algorithm>
#include <sstream>

#include <nlohmann/json.hpp>

#include "ppp_core/error.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp_msgs {

namespace {

/// `text` as a double-quoted XML attribute value; line breaks survive as character references.
/// @throws ppp::InvalidArgument naming `what` for text roslaunch would substitute ("$(").
std::string attribute(const std::string& text, const std::string& what) {
  if (text.find("$(") != std::string::npos) {
    throw ppp::InvalidArgument(what, "must not contain \"$(\" (roslaunch would substitute it): " + text);
  }
  std::string out;
  for (const char c : ppp::escapeMarkup(text)) {
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

void writeNode(std::ostream& out, const GraphNode& node, const std::string& indent) {
  const std::string what = node.agent.empty() ? node.name : node.agent;
  const bool nodelet = !node.nodelet.empty();
  out << indent << "<node pkg=" << attribute(nodelet ? "nodelet" : node.package, what)
      << " type=" << attribute(nodelet ? "nodelet" : node.type, what) << " name=" << attribute(node.name, what);
  if (!node.ns.empty()) out << " ns=" << attribute(node.ns, what);
  if (!node.machine.empty()) out << " machine=" << attribute(node.machine, what);
  const std::string args = nodelet ? "load " + node.nodelet + " " + node.manager + " --no-bond" +
                                         (node.args.empty() ? "" : " " + node.args)
                                   : node.args;
  if (!args.empty()) out << " args=" << attribute(args, what);
  out << " output=\"screen\"" << (node.required ? " required=\"true\"" : "");
  if (node.params.empty() && node.remaps.empty()) {
    out << "/>\n";
    return;
  }
  out << ">\n";
  for (const GraphParam& p : node.params) {
    out << indent << "  <param name=" << attribute(p.name, "~" + p.name) << " type=" << attribute(p.type, "~" + p.name)
        << " value=" << attribute(p.value, "~" + p.name) << "/>\n";
  }
  for (const GraphRemap& r : node.remaps) {
    out << indent << "  <remap from=" << attribute(r.from, what) << " to=" << attribute(r.to, what) << "/>\n";
  }
  out << indent << "</node>\n";
}

}  // namespace

std::string launchXml(const LaunchGraph& graph) {
  std::ostringstream out;
  out << "<launch>\n  <!-- " << ppp::escapeMarkup(graph.comment) << " -->\n";
  for (const GraphMachine& m : graph.machines) {
    out << "  <machine name=" << attribute(m.name, "host") << " address=" << attribute(m.address, "host")
        << " env-loader=" << attribute(m.env_loader, "env_loader") << " timeout=\"" << m.start_timeout << "\"/>\n";
  }
  for (const GraphParam& p : graph.params) {
    out << "  <param name=" << attribute(p.name, p.name) << " type=" << attribute(p.type, p.name)
        << " value=" << attribute(p.value, p.name) << "/>\n";
  }
  for (std::size_t i = 0; i < graph.nodes.size();) {
    const std::string& group = graph.nodes[i].group;
    if (group.empty()) {
      writeNode(out, graph.nodes[i++], "  ");
      continue;
    }
    out << "  <group ns=" << attribute(group, graph.nodes[i].agent) << ">\n";
    for (; i < graph.nodes.size() && graph.nodes[i].group == group; ++i) writeNode(out, graph.nodes[i], "    ");
    out << "  </group>\n";
  }
  out << "</launch>\n";
  return out.str();
}

std::string launchJson(const LaunchGraph& graph) {
  nlohmann::ordered_json json;
  json["comment"] = graph.comment;
  const auto required = std::find_if(graph.nodes.begin(), graph.nodes.end(), [](const GraphNode& n) { return n.required; });
  json["required"] = required == graph.nodes.end() ? "" : required->name;
  json["status_param"] = graph.status_param;
  json["machines"] = nlohmann::ordered_json::array();
  for (const GraphMachine& m : graph.machines) {
    nlohmann::ordered_json agents = nlohmann::ordered_json::array();
    for (const GraphNode& n : graph.nodes) {
      if (n.machine == m.name && !n.agent.empty() && std::find(agents.begin(), agents.end(), n.agent) == agents.end()) {
        agents.push_back(n.agent);
      }
    }
    json["machines"].push_back({{"name", m.name}, {"address", m.address}, {"env_loader", m.env_loader}, {"agents", agents}});
  }
  json["nodes"] = nlohmann::ordered_json::array();
  for (const GraphNode& n : graph.nodes) {
    nlohmann::ordered_json params = nlohmann::ordered_json::object();
    for (const GraphParam& p : n.params) params[p.name] = p.value;
    json["nodes"].push_back({{"package", n.package}, {"type", n.type}, {"name", n.name}, {"group", n.group},
                             {"ns", n.ns}, {"machine", n.machine}, {"agent", n.agent}, {"required", n.required},
                             {"args", n.args}, {"nodelet", n.nodelet}, {"manager", n.manager}, {"params", params}});
  }
  json["xml"] = launchXml(graph);
  return json.dump(2) + "\n";
}

}  // namespace ppp_msgs
