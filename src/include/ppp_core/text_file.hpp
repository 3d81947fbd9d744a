#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "ppp_core/stop.hpp"

namespace ppp {

/// Reads a whole file, refusing files larger than `max_bytes` before reading, asking `stop` between chunks of a
/// few megabytes. @throws IoError, Interrupted.
std::string readTextFile(const std::string& path, std::size_t max_bytes, const StopCheck& stop = {});

/// Writes `contents` to `path` through a temporary file and a rename, so readers never see half a file.
/// @throws IoError.
void writeFileAtomically(const std::string& path, const std::string& contents);

/// A file written block by block that replaces `path` only on commit(): readers see the old file or the whole new
/// one, never half of it, and a file too large to hold in memory at once is never held.
class AtomicFile {
 public:
  /// Opens the temporary file beside `path`. @throws IoError.
  explicit AtomicFile(const std::string& path);
  /// Removes the temporary file unless commit() put it in place.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  /// Appends `block`. @throws IoError naming `path` and the system's reason.
  void write(std::string_view block);
  /// Closes the file and renames it over `path`. @throws IoError naming `path` and the system's reason.
  void commit();

 private:
  [[noreturn]] void fail(const std::string& what);

  std::string path_;
  std::string temporary_;
  int fd_ = -1;
  bool committed_ = false;
};

}  // namespace ppp
