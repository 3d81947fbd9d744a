#pragma once

// Values that every source of an options struct (YAML, ROS parameters, command-line flags) must accept or refuse
// alike, derived from its declarations: each option's value in a valid base, its bounds, one step past them and
// a value of the wrong type. Tests of each source play the same cases (plus refusals that need more than a type).

#include <cmath>
#include <stdexcept>
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
    const bool integer = spec.kind == OptionKind::Integer;
    const double step = integer ? 1 : 0.5;
    if (std::isfinite(spec.bounds.min)) {
      cases.push_back({spec.name, caseNumber(spec.bounds.min), true});
      cases.push_back({spec.name, caseNumber(spec.bounds.min - step), false});
    }
    if (std::isfinite(spec.bounds.max)) {
      cases.push_back({spec.name, caseNumber(spec.bounds.max), true});
      cases.push_back({spec.name, caseNumber(spec.bounds.max + step), false});
    }
    if (integer || spec.kind == OptionKind::Number) cases.push_back({spec.name, "many", false});
    if (integer) cases.push_back({spec.name, "2.5", false});
    if (spec.kind == OptionKind::Boolean) cases.push_back({spec.name, "maybe", false});
    if (spec.kind == OptionKind::TextList) cases.push_back({spec.name, "{a: 1}", false});
    if (spec.kind == OptionKind::Cell) cases.push_back({spec.name, "[1, 2, 3]", false});
    if (spec.kind != OptionKind::TextList && spec.kind != OptionKind::Cell) cases.push_back({spec.name, "[a, b]", false});
    if (!spec.choices.empty()) cases.push_back({spec.name, "not_a_choice", false});
  }
  return cases;
}

/// A valid value of `spec` (as YAML text) other than the one in `options`, derived from its declaration: another
/// bound or a step inside them, the other boolean, another example, a longer text or list, a moved cell.
template <typename Options>
std::string differentOptionValue(const OptionSpec<Options>& spec, const Options& options) {
  const std::string current = spec.text(options);
  for (const OptionChoice& choice : spec.choices) {
    if (choice.name != current) return choice.name;
  }
  switch (spec.kind) {
    case OptionKind::Integer:
    case OptionKind::Number: {
      const double value = std::stod(current);
      const double step = spec.kind == OptionKind::Integer ? 1 : 0.25;
      if (std::isfinite(spec.bounds.min) && spec.bounds.min != value) return caseNumber(spec.bounds.min);
      if (std::isfinite(spec.bounds.max) && spec.bounds.max != value) return caseNumber(spec.bounds.max);
      return caseNumber(value + step <= spec.bounds.max ? value + step : value - step);
    }
    case OptionKind::Boolean: return current == "true" ? "false" : "true";
    case OptionKind::Text: return current.empty() || current == "''" ? "other" : current + "_other";
    case OptionKind::TextList: return current == "[]" ? "[other]" : current.substr(0, current.size() - 1) + ", other]";
    case OptionKind::Cell: return current == "[1, 1]" ? "[2, 1]" : "[1, 1]";
    case OptionKind::Custom: break;
  }
  for (const std::string& example : spec.examples) {
    if (example != current) return example;
  }
  throw std::logic_error("option '" + spec.name + "' declares no example other than its value " + current);
}

}  // namespace ppp
