#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "ppp_core/option_spec.hpp"

namespace ppp {

/// The declared options as a Markdown table: key (with `spelled` applied, e.g. "~" + name for a parameter or the
/// flag), value type and range, the value in `defaults`, whether it may change results (a resume refuses a
/// change of it), and the one-line doc.
template <typename Options>
std::string optionsMarkdownTable(const std::vector<OptionSpec<Options>>& specs, const Options& defaults,
                                 std::string (*spelled)(const OptionSpec<Options>&)) {
  std::ostringstream out;
  out << "| option | value | default | changes results | meaning |\n|---|---|---|---|---|\n";
  for (const OptionSpec<Options>& spec : specs) {
    const std::string range = spec.rangeText();
    const std::string value = spec.text(defaults);
    const std::string kind = spec.choices.empty() ? spec.type + (range.empty() ? "" : " " + range) : "one of " + spec.choiceList();
    out << "| `" << spelled(spec) << "` | " << kind << " | "
        << (value.empty() || value == "''" ? "" : "`" + value + "`") << " | " << (spec.affects_results ? "yes" : "no")
        << " | " << spec.docWithChoices() << " |\n";
  }
  return out.str();
}

}  // namespace ppp
