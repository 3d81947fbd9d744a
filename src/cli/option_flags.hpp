#pragma once

#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "ppp_core/error.hpp"
#include "ppp_core/option_spec.hpp"

namespace ppp {
namespace cli {

/// What --help shows as a flag's value: its kind and range ("INT in [2, 100000]", "X,Y", "A,B,...").
template <typename Options>
std::string flagValueName(const OptionSpec<Options>& spec) {
  if (!spec.choices.empty()) return spec.choiceList("|");
  const std::string range = spec.rangeText();
  const std::string in = range.empty() ? "" : (range[0] == '[' ? " in " : " ") + range;
  switch (spec.kind) {
    case OptionKind::Integer: return "INT" + in;
    case OptionKind::Number: return "FLOAT" + in;
    case OptionKind::Boolean: return "true|false";
    case OptionKind::Text: return "TEXT";
    case OptionKind::TextList: return "A,B,...";
    case OptionKind::Cell: return "X,Y";
    case OptionKind::Custom: break;
  }
  std::string examples;
  for (const std::string& example : spec.examples) examples += (examples.empty() ? "" : "|") + example;
  return examples.empty() ? "TEXT" : examples + "|...";
}

/// Adds one flag per declared option to `command`, documented from its declaration with `defaults`' value (or,
/// when `defaults` is null, as overriding the config file's); the texts given land in `given` (by flag name), for
/// applyOptionFlags().
template <typename Options>
void addOptionFlags(CLI::App* command, const std::vector<OptionSpec<Options>>& specs, const Options* defaults,
                    std::map<std::string, std::string>* given) {
  for (const OptionSpec<Options>& spec : specs) {
    const std::string value = defaults == nullptr ? "" : spec.text(*defaults);
    const std::string default_text = defaults == nullptr          ? "; default: the config file's"
                                     : value.empty() || value == "''" ? ""
                                                                      : "; default " + value;
    std::string& storage = (*given)[flagName(spec)];
    // The kind and range are the value's name; a value in a form of its own also says what it is.
    const std::string what = (spec.kind == OptionKind::Custom ? spec.type : "") + default_text;
    command->add_option(flagName(spec), storage, spec.docWithChoices() + (what.empty() ? "" : " (" + what.substr(what[0] == ';' ? 2 : 0) + ")"))
        ->type_name(flagValueName(spec));
  }
}

/// Applies the flags given on the command line over `options`, each read as its YAML value would be
/// ("a,b" for a list, "X,Y" for a cell); a flag given with the one it excludes is refused.
/// @throws InvalidArgument naming the flag and what was expected.
template <typename Options>
void applyOptionFlags(const CLI::App& command, const std::vector<OptionSpec<Options>>& specs,
                      const std::map<std::string, std::string>& given, Options* options) {
  for (const OptionSpec<Options>& spec : specs) {
    const std::string flag = flagName(spec);
    if (command.count(flag) == 0) continue;
    YAML::Node node;
    try {
      node = YAML::Load(given.at(flag));
    } catch (const YAML::Exception& e) {
      throw InvalidArgument(flag, "expected " + spec.type + ", got '" + given.at(flag) + "'");
    }
    const std::string problem = spec.set(options, node);
    if (!problem.empty()) throw InvalidArgument(flag, problem);
  }
  const auto given_flag = [&](const std::string& name) { return command.count(flagFor(name)) > 0; };
  if (const OptionSpec<Options>* both = exclusionBroken(specs, given_flag)) {
    throw InvalidArgument(flagName(*both), "give either " + flagFor(both->excludes) + " or " + flagName(*both) +
                                               ", not both");
  }
}

/// `error` (from validating options) naming the flag when that option was given as one, else unchanged.
template <typename Options>
InvalidArgument namingTheFlag(const CLI::App& command, const std::vector<OptionSpec<Options>>& specs,
                              const InvalidArgument& error) {
  for (const OptionSpec<Options>& spec : specs) {
    if (spec.name != error.name() || command.count(flagName(spec)) == 0) continue;
    return InvalidArgument(flagName(spec), error.problem());
  }
  return error;
}

/// applyOptionFlags(), then `options->validate()`, its error naming the flag when that option was given as one.
/// @throws InvalidArgument.
template <typename Options>
void applyAndValidateFlags(const CLI::App& command, const std::vector<OptionSpec<Options>>& specs,
                           const std::map<std::string, std::string>& given, Options* options) {
  applyOptionFlags(command, specs, given, options);
  try {
    options->validate();
  } catch (const InvalidArgument& e) {
    throw namingTheFlag(command, specs, e);
  }
}

}  // namespace cli
}  // namespace ppp
