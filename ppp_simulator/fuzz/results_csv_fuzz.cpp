// libFuzzer target for the results.csv reader that resuming relies on, in memory: parseResultsCsv must either
// return rows or throw ppp::Error; every row it returns must be written as a CSV line and read back to the same
// fields.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ppp_core/csv.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/fuzz_finding.hpp"
#include "ppp_simulator/results_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using ppp::fuzz::finding;
  namespace sim = ppp::simulator;
  std::vector<ppp::agents::EpisodeResult> rows;
  try {
    rows = sim::parseResultsCsv(std::string(reinterpret_cast<const char*>(data), size), "results.csv");
  } catch (const ppp::Error&) {
    return 0;
  }
  for (const ppp::agents::EpisodeResult& row : rows) {
    const std::vector<std::string> fields = ppp::agents::toCsvFields(row);
    const std::string line = ppp::csvLine(fields);
    try {
      if (ppp::agents::toCsvFields(ppp::agents::fromCsvFields(ppp::agents::splitCsvLine(line, "again.csv", 2), "again.csv", 2)) != fields) {
        finding("results_csv_fuzz", "a row changed when written and read back", line);
      }
    } catch (const ppp::Error& e) {
      finding("results_csv_fuzz", "a row read cannot be read back when written", line + "\n" + e.what());
    }
  }
  return 0;
}
