#pragma once

// Values that every source of an options struct (YAML, ROS parameters, command-line flags) must accept or refuse
// alike, derived from its declarations: each option's value in a valid base, its bounds, one step past them and
// a value of the wrong type. Tests of each source play the same cases (plus refusals that need more than a type).

#include <cmath>
#include <string>
#include <vector>

#include "ppp_core/option_spec.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {

/// One option set to one value (as YAML text) over a valid base.
struct OptionCase {
  std::string option;  ///< Declared name ("weights.goal").
  std::string value;   ///< YAML text of the value.
  bool accepted;       ///< Whether every source must accept it.
};

/// `value` as option text: integers without a decimal point.
inline std::string caseNumber(double value) {
  return value == std::floor(value) ? std::to_string(static_cast<long long>(value)) : formatShortest(value);
}

/// The cases of every option in `specs`, over `base` (whose values are accepted).
template <typename Options>
std::vector<OptionCase> declaredOptionCases(const std::vector<OptionSpec<Options>>& specs, const Options& base) {
  std::vector<OptionCase> cases;
  for (const OptionSpec<Options>& spec : specs) {
    const std::string text = spec.text(base);
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
    if (spec.type == "true or false") cases.push_back({spec.name, "maybe", false});
    if (spec.type == "a list of strings") cases.push_back({spec.name, "{a: 1}", false});
    if (spec.type == "a cell [x, y]") cases.push_back({spec.name, "[1, 2, 3]", false});
    if (spec.type != "a list of strings" && spec.type != "a cell [x, y]") cases.push_back({spec.name, "[a, b]", false});
  }
  return cases;
}

}  // namespace ppp
