// libFuzzer target for the experiment config reader, in memory: parseExperimentConfig must either return a valid
// config or throw ppp::Error. The YAML is read as /nonexistent/ppp_fuzz/experiment.yaml, so the files it names
// relative to itself (an agents list, a generator.yaml beside it) do not exist.

#include <cstddef>
#include <cstdint>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/fuzz_finding.hpp"
#include "ppp_simulator/experiment_config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ppp::simulator::ExperimentConfig config;
  try {
    config = ppp::simulator::parseExperimentConfig(std::string(reinterpret_cast<const char*>(data), size),
                                                   "/nonexistent/ppp_fuzz/experiment.yaml");
  } catch (const ppp::Error&) {
    return 0;
  }
  try {
    config.validate();
    ppp::simulator::experimentFingerprint(config);
  } catch (const ppp::Error& e) {
    ppp::fuzz::finding("experiment_yaml_fuzz", "an accepted config does not validate", e.what());
  }
  return 0;
}
