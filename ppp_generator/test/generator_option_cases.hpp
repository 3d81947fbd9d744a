#pragma once

// Test helper: values every source of generator options (YAML, ROS parameters, command-line flags) must accept
// or refuse alike, derived from the declarations: each option's default, its bounds, one past them, a value of
// the wrong type, and the refusals that need more than a type (unknown names).

#include <cmath>
#include <string>
#include <vector>

#include "ppp_generator/generator_options.hpp"

namespace ppp {
namespace generator {
namespace test {

/// One option set to one value (as YAML text) over the defaults.
struct OptionCase {
  std::string option;  ///< Declared name ("weights.goal").
  std::string value;   ///< YAML text of the value.
  bool accepted;       ///< Whether every source must accept it.
};

/// `value` as option text: integers without a decimal point.
inline std::string caseNumber(double value) {
  return value == std::floor(value) ? std::to_string(static_cast<long long>(value)) : formatShortest(value);
}

/// The cases of every declared generator option.
inline std::vector<OptionCase> generatorOptionCases() {
  std::vector<OptionCase> cases;
  const GeneratorOptions defaults;
  for (const OptionSpec<GeneratorOptions>& spec : generatorOptionSpecs()) {
    const std::string text = spec.text(defaults);
    cases.push_back({spec.name, text.empty() ? "[1, 1]" : text, true});
    const bool integer = spec.type.find("integer") != std::string::npos;
    const double step = integer ? 1 : 0.5;
    if (std::isfinite(spec.bounds.min)) {
      cases.push_back({spec.name, caseNumber(spec.bounds.min), true});
      cases.push_back({spec.name, caseNumber(spec.bounds.min - step), false});
    }
    if (std::isfinite(spec.bounds.max)) {
      cases.push_back({spec.name, caseNumber(spec.bounds.max), true});
      cases.push_back({spec.name, caseNumber(spec.bounds.max + step), false});
    }
    if (integer || spec.type == "a number") cases.push_back({spec.name, "many", false});
    if (integer) cases.push_back({spec.name, "2.5", false});
    if (spec.type == "a string") cases.push_back({spec.name, "[a, b]", false});
    if (spec.type == "a list of strings") cases.push_back({spec.name, "{a: 1}", false});
    if (spec.type == "a cell [x, y]") cases.push_back({spec.name, "[1, 2, 3]", false});
  }
  for (const auto& [option, value] : std::vector<std::pair<std::string, std::string>>{
           {"fitness", "hardest"}, {"characters", "all"}, {"replacement", "sideways"}, {"archive", "grid"},
           {"features", "[turns]"}, {"features", "[turns, width]"}, {"goal", "[0, 0]"}, {"start", "[20, 0]"},
           {"agents", "[bumper]"}}) {
    cases.push_back({option, value, false});
  }
  cases.push_back({"features", "[turns, visibility_goal]", true});
  return cases;
}

}  // namespace test
}  // namespace generator
}  // namespace ppp
