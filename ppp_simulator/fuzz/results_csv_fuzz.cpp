// libFuzzer target for the results.csv reader that resuming relies on: readResultsFile must either return rows
// or throw ppp::Error; rows it returns must be written and read back unchanged.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/fuzz_finding.hpp"
#include "ppp_simulator/results_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using ppp::fuzz::finding;
  const std::string path =
      ppp::fuzz::scratchFile("results.csv", std::string(reinterpret_cast<const char*>(data), size));
  std::vector<ppp::simulator::EpisodeResult> rows;
  try {
    rows = ppp::simulator::readResultsFile(path);
  } catch (const ppp::Error&) {
    return 0;
  }
  const std::string again = ppp::fuzz::scratchDirectory() + "/again.csv";
  try {
    {
      ppp::simulator::ResultsFile file(again);
      file.rewrite(rows);
    }
    if (ppp::simulator::readResultsFile(again).size() != rows.size()) finding("results_csv_fuzz", "rows lost", "");
  } catch (const ppp::Error& e) {
    finding("results_csv_fuzz", "rows read cannot be written and read back", e.what());
  }
  return 0;
}
