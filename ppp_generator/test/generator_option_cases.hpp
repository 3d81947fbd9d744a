#pragma once

// Test helper: values every source of generator options (YAML, ROS parameters, command-line flags) must accept
// or refuse alike: the declared cases (ppp_core/option_cases.hpp) and the refusals that need more than a type.

#include <string>
#include <utility>
#include <vector>

#include "ppp_core/option_cases.hpp"
#include "ppp_generator/generator_options.hpp"

namespace ppp {
namespace generator {
namespace test {

using ppp::OptionCase;

/// The cases of every declared generator option.
inline std::vector<OptionCase> generatorOptionCases() {
  std::vector<OptionCase> cases = declaredOptionCases(generatorOptionSpecs(), GeneratorOptions{});
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
