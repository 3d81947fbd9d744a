#pragma once

#include <sstream>
#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "ppp_core/error.hpp"

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

/// @throws ppp::InvalidArgument naming the parameter `name` unless `value` is a positive number.
inline void requirePositive(double value, const std::string& name) {
  if (!(value > 0)) throw ppp::InvalidArgument(name, "expected a positive number, got " + std::to_string(value));
}

}  // namespace ppp_msgs
