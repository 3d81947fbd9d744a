// libFuzzer target for the .ppp reader: parsePpp must either return a problem or throw ppp::Error.
// Any other exception, crash or sanitizer report is a finding, and so is a parsed problem that does not
// survive formatPpp -> parsePpp unchanged.

#include <cstddef>
#include <cstdint>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/fuzz_finding.hpp"
#include "ppp_core/ppp_file.hpp"

namespace {

[[noreturn]] void finding(const char* what, const std::string& detail) {
  ppp::fuzz::finding("ppp_parser_fuzz", what, detail);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  ppp::Problem parsed;
  try {
    parsed = ppp::parsePpp(text, "fuzz.ppp");
  } catch (const ppp::Error&) {
    return 0;  // rejecting bad input with a ppp::Error is the contract
  }
  std::string formatted;
  try {
    formatted = ppp::formatPpp(parsed);
  } catch (const ppp::Error& e) {
    finding("formatPpp refuses a problem parsePpp accepted", e.what());
  }
  ppp::Problem reparsed;
  try {
    reparsed = ppp::parsePpp(formatted, "formatted.ppp");
  } catch (const ppp::Error& e) {
    finding("parsePpp rejects formatPpp's output", std::string(e.what()) + "\n--- formatted ---\n" + formatted);
  }
  if (!(reparsed == parsed)) finding("formatPpp -> parsePpp changed the problem", formatted);
  return 0;
}
