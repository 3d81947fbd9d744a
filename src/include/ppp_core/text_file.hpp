#pragma once

#include <cstddef>
#include <string>

namespace ppp {

/// Reads a whole file, refusing files larger than `max_bytes` before reading. @throws IoError.
std::string readTextFile(const std::string& path, std::size_t max_bytes);

/// Writes `contents` to `path` through a temporary file and a rename, so readers never see half a file.
/// @throws IoError.
void writeFileAtomically(const std::string& path, const std::string& contents);

}  // namespace ppp
