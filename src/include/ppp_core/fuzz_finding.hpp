#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace ppp {
namespace fuzz {

// How the libFuzzer targets (src/fuzz, ppp_*/fuzz) report a finding.

/// Reports a finding of target `target` and aborts, so libFuzzer saves the input.
[[noreturn]] inline void finding(const char* target, const char* what, const std::string& detail) {
  std::fprintf(stderr, "%s: %s\n%s\n", target, what, detail.c_str());
  std::abort();
}

}  // namespace fuzz
}  // namespace ppp
