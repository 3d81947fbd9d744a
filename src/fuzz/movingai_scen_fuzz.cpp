// libFuzzer target for the MovingAI .scen reader: parseMovingAiScenarios must either return scenarios or throw
// ppp::Error. Any other exception, crash or sanitizer report is a finding, and so is a read that does not survive
// formatMovingAiScenarios -> parseMovingAiScenarios (checkTextRoundTrip): every field equal, the lengths within the
// rounding to the 8 decimals written, and writing the scenarios read back gives the same text.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ppp_core/fuzz_round_trip.hpp"
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
  const auto same = [](const std::vector<ppp::MovingAiScenario>& a, const std::vector<ppp::MovingAiScenario>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), sameScenario);
  };
  ppp::fuzz::checkTextRoundTrip("movingai_scen_fuzz", std::string(reinterpret_cast<const char*>(data), size),
                                "fuzz.scen", ppp::parseMovingAiScenarios, ppp::formatMovingAiScenarios, same);
  return 0;
}
