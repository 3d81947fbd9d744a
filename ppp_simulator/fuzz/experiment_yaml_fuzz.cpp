// libFuzzer target for the experiment config reader: loadExperimentConfig must either return a valid config or
// throw ppp::Error (the input is written to a file, as the reader reads files).

#include <cstddef>
#include <cstdint>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/fuzz_finding.hpp"
#include "ppp_simulator/experiment_config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path =
      ppp::fuzz::scratchFile("experiment.yaml", std::string(reinterpret_cast<const char*>(data), size));
  ppp::simulator::ExperimentConfig config;
  try {
    config = ppp::simulator::loadExperimentConfig(path);
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
