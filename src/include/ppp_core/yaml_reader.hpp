#pragma once

#include <cstddef>
#include <set>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "ppp_core/error.hpp"

namespace ppp {

/// Largest YAML file loadYamlFile() reads, checked before reading it.
constexpr std::size_t kMaxYamlBytes = 16u << 20;

/// Loads a YAML file. @throws IoError when unreadable, ParseError "<file>:<line>: yaml: ..." on bad syntax.
YAML::Node loadYamlFile(const std::string& path);

/// Parses YAML text from `source` (a file or parameter name for errors). @throws ParseError.
YAML::Node parseYaml(const std::string& text, const std::string& source);

/// Where two YAML documents first differ, as a person reads it: "connectivity: absent there, 8 here" or
/// "agents[2].planner_node: 'a/b' there, 'c/d' here" (`there` names the first document, `here` the second);
/// "" when they hold the same data. Mapping keys are compared in the order of `here`, then keys only `there` has.
std::string yamlDifference(const YAML::Node& there, const YAML::Node& here);

/// Reads the keys of one YAML mapping into typed fields, remembering which keys were used so that an
/// unknown (misspelt) key is reported with its line instead of being silently ignored.
class YamlMapReader {
 public:
  /// Wraps a mapping node; `source` names the file and `context` the enclosing key ("" at top level).
  /// @throws ParseError when the node is not a mapping.
  YamlMapReader(const YAML::Node& node, std::string source, std::string context = "");

  /// Reads `key` into `value` when present; returns whether it was. @throws ParseError on a wrong type.
  template <typename T>
  bool read(const std::string& key, T* value) {
    const YAML::Node child = lookup(key);
    if (!child) return false;
    try {
      *value = child.as<T>();
    } catch (const YAML::Exception&) {
      fail(child, key, "expected " + typeName(value) + ", got '" + scalarText(child) + "'");
    }
    return true;
  }

  /// The child node under `key` (marked as known), or an undefined node when absent.
  YAML::Node lookup(const std::string& key);

  /// Throws ParseError naming the first key that no read()/lookup() asked for, listing the valid ones.
  void rejectUnknownKeys() const;

  /// Throws ParseError "<source>:<line>: <context.key>: <what>" pointing at `node`.
  [[noreturn]] void fail(const YAML::Node& node, const std::string& key, const std::string& what) const;

  /// The file being read.
  const std::string& source() const { return source_; }

  /// Dotted name of `key` within this mapping, e.g. "weights.goal".
  std::string fieldName(const std::string& key) const { return context_.empty() ? key : context_ + "." + key; }

 private:
  static std::string scalarText(const YAML::Node& node);
  static std::string typeName(const bool*) { return "true or false"; }
  static std::string typeName(const int*) { return "an integer"; }
  static std::string typeName(const long*) { return "an integer"; }
  static std::string typeName(const unsigned long*) { return "a non-negative integer"; }
  static std::string typeName(const double*) { return "a number"; }
  static std::string typeName(const std::string*) { return "a string"; }
  static std::string typeName(const std::vector<int>*) { return "a list of integers"; }
  static std::string typeName(const std::vector<std::string>*) { return "a list of strings"; }

  YAML::Node node_;
  std::string source_;
  std::string context_;
  std::set<std::string> known_;
};

}  // namespace ppp
