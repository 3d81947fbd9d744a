#pragma once

// The default experiment's ten built-in agent configurations (config/agents.yaml), for the benchmarks.

#include <string>

#include "ppp_agents/agent_config.hpp"

namespace ppp::bench {

/// How many configurations defaultAgent() knows.
constexpr int kDefaultAgentCount = 10;

/// Configuration `index` (in [0, kDefaultAgentCount)) of the default experiment's built-in agents, in the order of
/// config/agents.yaml.
inline agents::AgentConfig defaultAgent(int index) {
  static const char* const kNames[kDefaultAgentCount] = {
      "astar",    "random",           "wall_follower_left", "wall_follower_right", "explorer", "long_term_explorer",
      "explorer_memory_5x5", "explorer_noise_0.1", "bumper", "decision_bumper"};
  agents::AgentConfig config;
  config.name = kNames[index];
  config.type = config.name;
  if (config.name == "explorer_memory_5x5") config.type = "explorer", config.memory_window = 5;
  if (config.name == "explorer_noise_0.1") config.type = "explorer", config.sensor_noise = 0.1;
  return config;
}

}  // namespace ppp::bench
