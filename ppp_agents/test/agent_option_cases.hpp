#pragma once

// Test helper: values every source of agent options (agents YAML, agent node and bridge parameters, `ppp
// simulate` flags) must accept or refuse alike: the declared cases over an explorer (ppp_core/option_cases.hpp)
// and the refusals that need more than a type.

#include <algorithm>
#include <string>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_core/option_cases.hpp"

namespace ppp {
namespace agents {
namespace test {

/// The explorer every case is applied over.
inline AgentConfig caseBase() {
  AgentConfig base;
  base.name = base.type = "explorer";
  return base;
}

/// The cases of the options in `specs` (a source's selection of agentOptionSpecs()).
inline std::vector<OptionCase> agentOptionCases(const std::vector<OptionSpec<AgentConfig>>& specs) {
  std::vector<OptionCase> cases = declaredOptionCases(specs, caseBase());
  // An explorer refuses every instances value but 0 (only planner agents run as several instances).
  cases.erase(std::remove_if(cases.begin(), cases.end(),
                             [](const OptionCase& c) { return c.option == "instances" && c.accepted && c.value != "0"; }),
              cases.end());
  const std::vector<OptionCase> more = {
      {"type", "astar", true},          {"type", "robot", false},        {"memory", "5x5", true},
      {"memory", "4x4", false},         {"memory", "5x3", false},        {"memory", "5", false},
      {"name", "''", false},            {"prior_map", "true", false},    {"planner_node", "a/b", false},
      {"host", "robot-2.lab", true},    {"host", "'two words'", false},  {"planner_args", "_a:=1", false},
      {"instances", "2", false},
  };
  for (const OptionCase& c : more) {
    const bool declared =
        std::any_of(specs.begin(), specs.end(), [&](const OptionSpec<AgentConfig>& s) { return s.name == c.option; });
    if (declared) cases.push_back(c);
  }
  return cases;
}

}  // namespace test
}  // namespace agents
}  // namespace ppp
