#include "ppp_core/yaml_reader.hpp"

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

}  // namespace ppp
