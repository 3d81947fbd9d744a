#pragma once

#include <sstream>
#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "ppp_core/error.hpp"
#include "ppp_core/option_spec.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp_msgs {

/// Reads an optional private parameter of type T into `value`; a present parameter of another type is an error
/// naming `~name` and what was `expected`. Returns whether it was present.
template <typename T>
bool readParameter(const ros::NodeHandle& nh, const std::string& name, T* value, const std::string& expected) {
  if (!nh.hasParam(name)) return false;
  if (!nh.getParam(name, *value)) throw ppp::InvalidArgument("~" + name, "expected " + expected);
  return true;
}

/// Reads `~name` into `values` when it is set: a list of strings, or one comma-separated string (what
/// `_name:=a,b` gives on a command line). Returns whether it was set. @throws ppp::InvalidArgument naming it.
inline bool readStringList(const ros::NodeHandle& nh, const std::string& name, std::vector<std::string>* values) {
  if (!nh.hasParam(name)) return false;
  if (nh.getParam(name, *values)) return true;
  std::string text;
  if (!nh.getParam(name, text)) throw ppp::InvalidArgument("~" + name, "expected a list of strings or \"a,b,...\"");
  values->clear();
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');) {
    if (!item.empty()) values->push_back(item);
  }
  return true;
}

/// A parameter value as the YAML node its config file would hold (so parameters and YAML read alike).
/// @throws ppp::InvalidArgument naming `~name` for a struct or binary value.
inline YAML::Node parameterYaml(const XmlRpc::XmlRpcValue& value, const std::string& name) {
  XmlRpc::XmlRpcValue v = value;  // the accessors are not const
  switch (v.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean: return YAML::Node(static_cast<bool>(v) ? "true" : "false");
    case XmlRpc::XmlRpcValue::TypeInt: return YAML::Node(std::to_string(static_cast<int>(v)));
    case XmlRpc::XmlRpcValue::TypeDouble: return YAML::Node(ppp::formatShortest(static_cast<double>(v)));
    case XmlRpc::XmlRpcValue::TypeString: return YAML::Node(static_cast<std::string>(v));
    case XmlRpc::XmlRpcValue::TypeArray: {
      YAML::Node list(YAML::NodeType::Sequence);
      for (int i = 0; i < v.size(); ++i) list.push_back(parameterYaml(v[i], name));
      return list;
    }
    default: throw ppp::InvalidArgument("~" + name, "expected a value or a list of values, got a mapping or binary");
  }
}

/// A YAML value as the parameter a config file's `rosparam` (or `_name:=VALUE`) would set: integers, numbers,
/// booleans, strings, lists and mappings as XML-RPC values (the inverse of parameterYaml()).
inline XmlRpc::XmlRpcValue yamlParameter(const YAML::Node& node) {
  XmlRpc::XmlRpcValue value;
  if (node.IsSequence()) {
    value.setSize(static_cast<int>(node.size()));
    for (std::size_t i = 0; i < node.size(); ++i) value[static_cast<int>(i)] = yamlParameter(node[i]);
    return value;
  }
  if (node.IsMap()) {
    for (const auto& entry : node) value[entry.first.as<std::string>()] = yamlParameter(entry.second);
    return value;
  }
  int integer = 0;
  double number = 0;
  if (YAML::convert<int>::decode(node, integer)) return XmlRpc::XmlRpcValue(integer);
  if (YAML::convert<double>::decode(node, number)) return XmlRpc::XmlRpcValue(number);
  if (node.Scalar() == "true" || node.Scalar() == "false") return XmlRpc::XmlRpcValue(node.Scalar() == "true");
  return XmlRpc::XmlRpcValue(node.Scalar());
}

/// The parameter name of a declared option: dotted names as slashes ("weights.goal" as "weights/goal").
inline std::string parameterName(std::string option) {
  for (char& c : option) c = c == '.' ? '/' : c;
  return option;
}

/// Reads every declared option that is set as a `~` parameter (dotted names as "~weights/goal") over `options`,
/// each as its YAML value would be read; one set with the option it excludes is refused. Returns how many were
/// set. @throws ppp::InvalidArgument naming `~name`.
template <typename Options>
int readOptionParameters(const ros::NodeHandle& nh, const std::vector<ppp::OptionSpec<Options>>& specs,
                         Options* options) {
  int found = 0;
  for (const ppp::OptionSpec<Options>& spec : specs) {
    const std::string name = parameterName(spec.name);
    XmlRpc::XmlRpcValue value;
    if (!nh.hasParam(name) || !nh.getParam(name, value)) continue;
    const std::string problem = spec.set(options, parameterYaml(value, name));
    if (!problem.empty()) throw ppp::InvalidArgument("~" + name, problem);
    ++found;
  }
  const auto given = [&](const std::string& name) { return nh.hasParam(parameterName(name)); };
  if (const ppp::OptionSpec<Options>* both = ppp::exclusionBroken(specs, given)) {
    throw ppp::InvalidArgument("~" + parameterName(both->name), "give either ~" + parameterName(both->excludes) +
                                                                    " or ~" + parameterName(both->name) + ", not both");
  }
  return found;
}

/// `error`, naming an option, as the error of its `~` parameter ("weights.goal" as "~weights/goal").
inline ppp::InvalidArgument parameterError(const ppp::InvalidArgument& error) {
  return ppp::InvalidArgument("~" + parameterName(error.name()), error.problem());
}

/// Validates options read from `~` parameters (their validate()); an error names the parameter ("~weights/goal"
/// for the option "weights.goal"). @throws ppp::InvalidArgument.
template <typename Options>
void validateParameters(const Options& options) {
  try {
    options.validate();
  } catch (const ppp::InvalidArgument& e) {
    throw parameterError(e);
  }
}

/// @throws ppp::InvalidArgument naming the parameter `name` unless `value` is a positive number.
inline void requirePositive(double value, const std::string& name) {
  if (!(value > 0)) throw ppp::InvalidArgument(name, "expected a positive number, got " + std::to_string(value));
}

}  // namespace ppp_msgs
