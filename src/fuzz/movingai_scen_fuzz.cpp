// libFuzzer target for the MovingAI .scen reader: parseMovingAiScenarios must either return scenarios or throw
// ppp::Error. Any other exception, crash or sanitizer report is a finding, and so is a read that does not survive
// formatMovingAiScenarios -> parseMovingAiScenarios: every field equal, the lengths
// within the rounding to the 8 decimals written, and writing the scenarios read back gives the same text.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/fuzz_finding.hpp"
#include "ppp_core/movingai_scen.hpp"

namespace {

bool sameScenario(const ppp::MovingAiScenario& a, const ppp::MovingAiScenario& b) {
  return a.bucket == b.bucket && a.map == b.map && a.map_width == b.map_width && a.map_height == b.map_height &&
         a.start == b.start && a.goal == b.goal &&
         // half a unit of the 8th decimal, plus the doubles' own rounding of the written and the read value
         std::fabs(a.optimal_length - b.optimal_length) <= (5e-9 + 1e-15) * std::fmax(1.0, a.optimal_length);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const char* target = "movingai_scen_fuzz";
  std::vector<ppp::MovingAiScenario> read;
  try {
    read = ppp::parseMovingAiScenarios(std::string(reinterpret_cast<const char*>(data), size), "fuzz.scen");
  } catch (const ppp::Error&) {
    return 0;  // rejecting bad input with a ppp::Error is the contract
  }
  const std::string formatted = ppp::formatMovingAiScenarios(read);
  std::vector<ppp::MovingAiScenario> reread;
  try {
    reread = ppp::parseMovingAiScenarios(formatted, "formatted fuzz.scen");
  } catch (const ppp::Error& e) {
    ppp::fuzz::finding(target, "the reader rejects the writer's output",
                       std::string(e.what()) + "\n--- formatted ---\n" + formatted);
  }
  if (reread.size() != read.size()) ppp::fuzz::finding(target, "writing and reading again changed the count", formatted);
  for (std::size_t i = 0; i < read.size(); ++i) {
    if (!sameScenario(read[i], reread[i])) ppp::fuzz::finding(target, "writing and reading again changed a scenario", formatted);
  }
  if (ppp::formatMovingAiScenarios(reread) != formatted) {
    ppp::fuzz::finding(target, "writing what was read back gave different text", formatted);
  }
  return 0;
}
