// libFuzzer target for the map_server reader: the input is a map YAML and its PGM image, separated by the line
// "%%PGM%%" (the YAML's image key names map.pgm). readMapYaml must either return a problem or throw ppp::Error;
// any other exception, crash or sanitizer report is a finding, and so is a read problem that does not survive
// writeMapYaml -> readMapYaml unchanged.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/map_yaml.hpp"

namespace {

[[noreturn]] void finding(const char* what, const std::string& detail) {
  std::fprintf(stderr, "map_yaml_fuzz: %s\n%s\n", what, detail.c_str());
  std::abort();
}

/// A directory of this process's own for the files of one input.
const std::string& scratch() {
  static const std::string dir = [] {
    char name[] = "/tmp/map_yaml_fuzz.XXXXXX";
    if (::mkdtemp(name) == nullptr) finding("cannot make a scratch directory", name);
    return std::string(name);
  }();
  return dir;
}

void writeFile(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::string separator = "\n%%PGM%%\n";
  const std::size_t at = input.find(separator);
  writeFile(scratch() + "/map.yaml", input.substr(0, at));
  writeFile(scratch() + "/map.pgm", at == std::string::npos ? std::string() : input.substr(at + separator.size()));
  ppp::Problem read;
  ppp::MapYamlOptions geometry;
  try {
    read = ppp::readMapYaml(scratch() + "/map.yaml", {}, &geometry);
  } catch (const ppp::Error&) {
    return 0;  // rejecting bad input with a ppp::Error is the contract
  }
  try {
    ppp::writeMapYaml(read, scratch() + "/again.yaml", geometry);
  } catch (const ppp::Error& e) {
    finding("writeMapYaml refuses a map readMapYaml accepted", e.what());
  }
  ppp::Problem reread;
  try {
    reread = ppp::readMapYaml(scratch() + "/again.yaml");
  } catch (const ppp::Error& e) {
    finding("readMapYaml rejects writeMapYaml's output", e.what());
  }
  if (!(reread == read)) finding("writeMapYaml -> readMapYaml changed the problem", input.substr(0, at));
  return 0;
}
