// libFuzzer target for the .ppp reader: parsePpp must either return a problem or throw ppp::Error.
// Any other exception, crash or sanitizer report is a finding, and so is a parsed problem that does not
// survive formatPpp -> parsePpp unchanged.

#include <cstddef>
#include <cstdint>
#include <string>

#include "ppp_core/fuzz_round_trip.hpp"
#include "ppp_core/ppp_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ppp::fuzz::checkTextRoundTrip("ppp_parser_fuzz", std::string(reinterpret_cast<const char*>(data), size), "fuzz.ppp",
                                ppp::parsePpp, ppp::formatPpp);
  return 0;
}
