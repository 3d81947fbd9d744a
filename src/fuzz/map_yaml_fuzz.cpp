// libFuzzer target for the map_server reader, in memory: the input is a map YAML and its PGM image, separated by
// the line "%%PGM%%"; the YAML is read as fuzz/map.yaml, and its image key must name map.pgm (any other image is
// a missing file). parseMapYaml must either return a problem or throw ppp::Error; any other exception, crash or
// sanitizer report is a finding, and so is a read problem that does not survive formatMapYaml -> parseMapYaml
// unchanged.

#include <cstddef>
#include <cstdint>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/fuzz_finding.hpp"
#include "ppp_core/map_yaml.hpp"

namespace {

/// The one image there is: `pgm` at `path`.
ppp::MapImageSource imageAt(const std::string& path, const std::string& pgm) {
  return [path, pgm](const std::string& image_path) -> std::string {
    if (image_path != path) throw ppp::IoError(image_path, "no such file");
    return pgm;
  };
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using ppp::fuzz::finding;
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::string separator = "\n%%PGM%%\n";
  const std::size_t at = input.find(separator);
  const std::string yaml = input.substr(0, at);
  const std::string pgm = at == std::string::npos ? std::string() : input.substr(at + separator.size());
  ppp::Problem read;
  ppp::MapYamlOptions geometry;
  try {
    read = ppp::parseMapYaml(yaml, "fuzz/map.yaml", imageAt("fuzz/map.pgm", pgm), {}, &geometry);
  } catch (const ppp::Error&) {
    return 0;  // rejecting bad input with a ppp::Error is the contract
  }
  ppp::MapYamlText again;
  try {
    again = ppp::formatMapYaml(read, "again.pgm", geometry);
  } catch (const ppp::Error& e) {
    finding("map_yaml_fuzz", "formatMapYaml refuses a map parseMapYaml accepted", e.what());
  }
  ppp::Problem reread;
  try {
    reread = ppp::parseMapYaml(again.yaml, "again.yaml", imageAt("again.pgm", again.pgm));
  } catch (const ppp::Error& e) {
    finding("map_yaml_fuzz", "parseMapYaml rejects formatMapYaml's output", e.what());
  }
  if (!(reread == read)) finding("map_yaml_fuzz", "formatMapYaml -> parseMapYaml changed the problem", yaml);
  return 0;
}
