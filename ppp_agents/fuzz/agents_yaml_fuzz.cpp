// libFuzzer target for the agents list reader: readAgentConfigs must either return valid configurations or
// throw ppp::Error.

#include <cstddef>
#include <cstdint>
#include <string>

#include "ppp_agents/agent_config.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/fuzz_finding.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<ppp::agents::AgentConfig> configs;
  try {
    const YAML::Node root = ppp::parseYaml(text, "agents.yaml");
    ppp::YamlMapReader reader(root, "agents.yaml");
    configs = ppp::agents::readAgentConfigs(reader, "agents");
    reader.rejectUnknownKeys();
  } catch (const ppp::Error&) {
    return 0;
  }
  for (const ppp::agents::AgentConfig& config : configs) {
    try {
      config.validate();
    } catch (const ppp::Error& e) {
      ppp::fuzz::finding("agents_yaml_fuzz", "an accepted configuration does not validate", e.what());
    }
  }
  return 0;
}
