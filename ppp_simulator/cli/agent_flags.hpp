#pragma once

#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "ppp_agents/agent_config.hpp"
#include "ppp_agents/episode_runner.hpp"

namespace ppp {
namespace cli {

/// The flags of a command that plays one agent: the agent's (agents::agentPlayOptionSpecs) and the episode's
/// (--budget, --sensor-range, --connectivity), declared in the agent and episode option tables.
class AgentFlags {
 public:
  /// Adds the flags to `command`; --agent is required.
  void add(CLI::App* command);
  /// The agent the flags give, named after its type (built in: planners play only through ROS).
  /// @throws InvalidArgument naming the flag.
  agents::AgentConfig agent() const;
  /// The episode options the flags give. @throws InvalidArgument naming the flag.
  EpisodeOptions episode() const;
  /// True when `flag` (e.g. "--budget") was given on the command line.
  bool given(const std::string& flag) const { return command_->count(flag) > 0; }

 private:
  CLI::App* command_ = nullptr;
  std::map<std::string, std::string> given_;
};

}  // namespace cli
}  // namespace ppp
