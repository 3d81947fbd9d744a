// libFuzzer target for the map_server reader: the input is a map YAML and its PGM image, separated by the line
// "%%PGM%%" (the YAML's image key names map.pgm). readMapYaml must either return a problem or throw ppp::Error;
// any other exception, crash or sanitizer report is a finding, and so is a read problem that does not survive
// writeMapYaml -> readMapYaml unchanged.

#include <cstddef>
#include <cstdint>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/fuzz_finding.hpp"
#include "ppp_core/map_yaml.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using ppp::fuzz::finding;
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::string separator = "\n%%PGM%%\n";
  const std::size_t at = input.find(separator);
  const std::string yaml = ppp::fuzz::scratchFile("map.yaml", input.substr(0, at));
  ppp::fuzz::scratchFile("map.pgm", at == std::string::npos ? std::string() : input.substr(at + separator.size()));
  ppp::Problem read;
  ppp::MapYamlOptions geometry;
  try {
    read = ppp::readMapYaml(yaml, {}, &geometry);
  } catch (const ppp::Error&) {
    return 0;  // rejecting bad input with a ppp::Error is the contract
  }
  const std::string again = ppp::fuzz::scratchDirectory() + "/again.yaml";
  try {
    ppp::writeMapYaml(read, again, geometry);
  } catch (const ppp::Error& e) {
    finding("map_yaml_fuzz", "writeMapYaml refuses a map readMapYaml accepted", e.what());
  }
  ppp::Problem reread;
  try {
    reread = ppp::readMapYaml(again);
  } catch (const ppp::Error& e) {
    finding("map_yaml_fuzz", "readMapYaml rejects writeMapYaml's output", e.what());
  }
  if (!(reread == read)) finding("map_yaml_fuzz", "writeMapYaml -> readMapYaml changed the problem", input.substr(0, at));
  return 0;
}
