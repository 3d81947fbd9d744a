// libFuzzer target for the generator options reader: parseGeneratorOptions must either return options or throw
// ppp::Error; options it returns must be written and read back to the same YAML.

#include <cstddef>
#include <cstdint>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/fuzz_finding.hpp"
#include "ppp_generator/generator_options.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using ppp::fuzz::finding;
  const std::string text(reinterpret_cast<const char*>(data), size);
  ppp::generator::GeneratorOptions options;
  try {
    options = ppp::generator::parseGeneratorOptions(text, "fuzz.yaml");
    options.validate();
  } catch (const ppp::Error&) {
    return 0;
  }
  const std::string written = ppp::generator::generatorOptionsYaml(options);
  try {
    const ppp::generator::GeneratorOptions again = ppp::generator::parseGeneratorOptions(written, "written.yaml");
    const std::string rewritten = ppp::generator::generatorOptionsYaml(again);
    if (rewritten != written) {
      finding("generator_yaml_fuzz", "YAML changed", written + "--- read back and written again ---\n" + rewritten);
    }
  } catch (const ppp::Error& e) {
    finding("generator_yaml_fuzz", "the reader rejects the writer's YAML", written + "\n" + e.what());
  }
  return 0;
}
