#pragma once

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include <unistd.h>

namespace ppp {
namespace fuzz {

// Helpers of the libFuzzer targets (src/fuzz, ppp_*/fuzz): reporting a finding and feeding file readers.

/// Reports a finding of target `target` and aborts, so libFuzzer saves the input.
[[noreturn]] inline void finding(const char* target, const char* what, const std::string& detail) {
  std::fprintf(stderr, "%s: %s\n%s\n", target, what, detail.c_str());
  std::abort();
}

/// A directory of this process's own for the files a target writes (made once).
inline const std::string& scratchDirectory() {
  static const std::string dir = [] {
    char name[] = "/tmp/ppp_fuzz.XXXXXX";
    if (::mkdtemp(name) == nullptr) finding("fuzz", "cannot make a scratch directory", name);
    return std::string(name);
  }();
  return dir;
}

/// Writes `bytes` to `name` in the scratch directory and returns its path.
inline std::string scratchFile(const std::string& name, const std::string& bytes) {
  const std::string path = scratchDirectory() + "/" + name;
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  return path;
}

}  // namespace fuzz
}  // namespace ppp
