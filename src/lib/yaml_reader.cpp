#include "ppp_core/yaml_reader.hpp"

#include <algorithm>
#include <utility>

#include "ppp_core/text_file.hpp"

namespace ppp {

YAML::Node loadYamlFile(const std::string& path) { return parseYaml(readTextFile(path, kMaxYamlBytes), path); }

YAML::Node parseYaml(const std::string& text, const std::string& source) {
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ParseError(source, e.mark.line + 1, "yaml", e.msg);
  }
}

YamlMapReader::YamlMapReader(const YAML::Node& node, std::string source, std::string context)
    : node_(node), source_(std::move(source)), context_(std::move(context)) {
  if (!node_.IsMap()) {
    const int line = node_.IsDefined() ? node_.Mark().line + 1 : 1;
    throw ParseError(source_, line, context_.empty() ? "yaml" : context_, "expected a mapping of key: value");
  }
}

YAML::Node YamlMapReader::lookup(const std::string& key) {
  known_.insert(key);
  return node_[key];
}

void YamlMapReader::rejectUnknownKeys() const {
  for (const auto& entry : node_) {
    if (!entry.first.IsScalar()) {
      throw ParseError(source_, entry.first.Mark().line + 1, context_.empty() ? "yaml" : context_,
                       "expected plain keys, got a list or mapping as a key");
    }
    const std::string key = entry.first.Scalar();
    if (known_.count(key) != 0) continue;
    std::string valid;
    for (const std::string& k : known_) valid += (valid.empty() ? "" : ", ") + k;
    throw ParseError(source_, entry.first.Mark().line + 1, fieldName(key), "unknown key; valid keys: " + valid);
  }
}

void YamlMapReader::fail(const YAML::Node& node, const std::string& key, const std::string& what) const {
  throw ParseError(source_, node.Mark().line + 1, fieldName(key), what);
}

std::string YamlMapReader::scalarText(const YAML::Node& node) {
  if (node.IsScalar()) return node.Scalar();
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

namespace {

/// A node as a difference shows it: a scalar as itself, else what it is.
std::string shownNode(const YAML::Node& node) {
  if (!node || node.IsNull()) return "absent";
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  return node.IsMap() ? "a mapping" : "a list of " + std::to_string(node.size());
}

std::string differenceAt(const YAML::Node& there, const YAML::Node& here, const std::string& path) {
  const auto child = [&path](const std::string& key) { return path.empty() ? key : path + "." + key; };
  const std::string at = path.empty() ? "the document" : path;
  if (there && here && there.IsMap() && here.IsMap()) {
    for (const auto& entry : here) {
      const std::string key = entry.first.Scalar();
      const std::string found = differenceAt(there[key], entry.second, child(key));
      if (!found.empty()) return found;
    }
    for (const auto& entry : there) {
      const std::string key = entry.first.Scalar();
      if (!here[key]) return child(key) + ": " + shownNode(entry.second) + " there, absent here";
    }
    return "";
  }
  if (there && here && there.IsSequence() && here.IsSequence()) {
    for (std::size_t i = 0; i < std::min(there.size(), here.size()); ++i) {
      const std::string found = differenceAt(there[i], here[i], path + "[" + std::to_string(i) + "]");
      if (!found.empty()) return found;
    }
    if (there.size() == here.size()) return "";
    return at + ": " + std::to_string(there.size()) + " items there, " + std::to_string(here.size()) + " here";
  }
  const bool same = (!there || there.IsNull()) == (!here || here.IsNull()) &&
                    (!there || there.IsNull() || (there.IsScalar() && here.IsScalar() && there.Scalar() == here.Scalar()));
  return same ? "" : at + ": " + shownNode(there) + " there, " + shownNode(here) + " here";
}

}  // namespace

std::string yamlDifference(const YAML::Node& there, const YAML::Node& here) { return differenceAt(there, here, ""); }

}  // namespace ppp
