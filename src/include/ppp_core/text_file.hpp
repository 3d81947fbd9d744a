#pragma once

#include <cstddef>
#include <string>

#include "ppp_core/stop.hpp"

namespace ppp {

/// Reads a whole file, refusing files larger than `max_bytes` before reading, asking `stop` between chunks of a
/// few megabytes. @throws IoError, Interrupted.
std::string readTextFile(const std::string& path, std::size_t max_bytes, const StopCheck& stop = {});

/// Writes `contents` to `path` through a temporary file and a rename, so readers never see half a file.
/// @throws IoError.
void writeFileAtomically(const std::string& path, const std::string& contents);

}  // namespace ppp
