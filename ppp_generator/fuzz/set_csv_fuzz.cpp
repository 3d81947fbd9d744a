// libFuzzer target for the set.csv reader (a set directory's index of its PPP files): parseSetCsv must either
// return file names or throw ppp::Error; every name it returns must be a .ppp file directly in the set's
// directory (no path separator, control character or quote), each listed once.

#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/fuzz_finding.hpp"
#include "ppp_generator/set_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using ppp::fuzz::finding;
  std::vector<std::string> files;
  try {
    files = ppp::generator::parseSetCsv(std::string(reinterpret_cast<const char*>(data), size), "set.csv");
  } catch (const ppp::Error&) {
    return 0;
  }
  if (files.empty()) finding("set_csv_fuzz", "a set of no PPPs was accepted", "");
  std::set<std::string> seen;
  for (const std::string& file : files) {
    if (!seen.insert(file).second) finding("set_csv_fuzz", "a file listed twice was accepted", file);
    if (file.size() <= 4 || file.compare(file.size() - 4, 4, ".ppp") != 0) {
      finding("set_csv_fuzz", "a file name that is not a .ppp was accepted", file);
    }
    for (unsigned char c : file) {
      if (c < 0x20 || c == 0x7f || c == '/' || c == '\\' || c == '"') {
        finding("set_csv_fuzz", "a file name outside the set's directory or with a control byte", file);
      }
    }
  }
  return 0;
}
