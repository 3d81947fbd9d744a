#pragma once

#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/option_spec.hpp"
#include "ppp_core/yaml_reader.hpp"

namespace ppp {

/// Reads every declared option present in the mapping of `reader` into `options` (dotted names are keys of
/// nested mappings: "weights.goal") and refuses unknown keys of those nested mappings; the caller refuses unknown
/// keys of `reader` once everything it holds is read; an option given with the one it excludes is refused.
/// @throws ParseError naming file, line and key.
template <typename Options>
void readOptionsYaml(YamlMapReader& reader, const std::vector<OptionSpec<Options>>& specs, Options* options) {
  std::map<std::string, std::unique_ptr<YamlMapReader>> groups;
  std::map<std::string, std::pair<YamlMapReader*, YAML::Node>> given;  // by option name: where it was read
  for (const OptionSpec<Options>& spec : specs) {
    const std::size_t dot = spec.name.find('.');
    YamlMapReader* at = &reader;
    std::string key = spec.name;
    if (dot != std::string::npos) {
      const std::string group = spec.name.substr(0, dot);
      key = spec.name.substr(dot + 1);
      if (groups.count(group) == 0) {
        const YAML::Node node = reader.lookup(group);
        groups[group] = node ? std::make_unique<YamlMapReader>(node, reader.source(), reader.fieldName(group)) : nullptr;
      }
      at = groups[group].get();
      if (at == nullptr) continue;
    }
    const YAML::Node node = at->lookup(key);
    if (!node) continue;
    given[spec.name] = {at, node};
    const std::string problem = spec.set(options, node);
    if (!problem.empty()) at->fail(node, key, problem);
  }
  if (const OptionSpec<Options>* both = exclusionBroken(specs, [&](const std::string& n) { return given.count(n) > 0; })) {
    const auto& [at, node] = given.at(both->name);
    at->fail(node, both->name.substr(both->name.find('.') + 1),
             "give either " + both->excludes + " or " + both->name + ", not both");
  }
  for (const auto& group : groups) {
    if (group.second) group.second->rejectUnknownKeys();
  }
}

/// The options as YAML in declaration order (nested mappings for dotted names); with `docs`, each line carries
/// its one-line doc and range as a comment, and unset optional options appear commented out.
template <typename Options>
std::string optionsYaml(const std::vector<OptionSpec<Options>>& specs, const Options& options, bool docs) {
  std::ostringstream out;
  std::string group;
  for (const OptionSpec<Options>& spec : specs) {
    const std::size_t dot = spec.name.find('.');
    const std::string this_group = dot == std::string::npos ? "" : spec.name.substr(0, dot);
    if (!this_group.empty() && this_group != group) out << this_group << ":\n";
    group = this_group;
    const std::string key = (group.empty() ? "" : "  ") + spec.name.substr(dot == std::string::npos ? 0 : dot + 1);
    const std::string value = spec.text(options);
    if (!docs) {
      if (!value.empty()) out << key << ": " << value << "\n";
      continue;
    }
    std::string line = (value.empty() ? "# " + key + ":" : key + ": " + value);
    line.resize(std::max<std::size_t>(line.size() + 1, 30), ' ');
    const std::string range = spec.rangeText();
    out << line << "# " << spec.docWithChoices() << (range.empty() || !spec.choices.empty() ? "" : " " + range) << "\n";
  }
  return out.str();
}

/// Checks every declared option's range. @throws InvalidArgument naming the first option out of range.
template <typename Options>
void checkOptionRanges(const std::vector<OptionSpec<Options>>& specs, const Options& options) {
  for (const OptionSpec<Options>& spec : specs) {
    const std::string problem = spec.check(options);
    if (!problem.empty()) throw InvalidArgument(spec.name, problem);
  }
}

}  // namespace ppp
