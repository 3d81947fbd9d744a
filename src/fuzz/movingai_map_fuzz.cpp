// libFuzzer target for the MovingAI .map reader: parseMovingAiMap must either return a problem or throw ppp::Error.
// Any other exception, crash or sanitizer report is a finding, and so is a read problem that does not survive
// formatMovingAiMap -> parseMovingAiMap unchanged (start and goal are the defaults, the first and last free cells,
// both times).

#include <cstddef>
#include <cstdint>
#include <string>

#include "ppp_core/fuzz_round_trip.hpp"
#include "ppp_core/movingai_map.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ppp::fuzz::checkTextRoundTrip(
      "movingai_map_fuzz", std::string(reinterpret_cast<const char*>(data), size), "fuzz.map",
      [](const std::string& text, const std::string& source) { return ppp::parseMovingAiMap(text, source); },
      ppp::formatMovingAiMap);
  return 0;
}
