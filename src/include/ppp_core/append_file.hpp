#pragma once

#include <cstddef>
#include <string>

namespace ppp {

/// Writes all of `data` to file descriptor `fd`, retrying short writes and EINTR; false (errno set) on failure.
bool writeFully(int fd, const char* data, std::size_t size);

/// A file that grows by whole blocks: a block is written entirely or not at all (what a failed write left of it
/// is cut off again), so the file never ends in half a block, even when the disk fills up.
class AppendFile {
 public:
  /// Opens `path` for appending, creating it, or emptying it when `truncate`. @throws IoError.
  AppendFile(const std::string& path, bool truncate);
  /// Closes the file.
  ~AppendFile();
  AppendFile(const AppendFile&) = delete;
  AppendFile& operator=(const AppendFile&) = delete;
  /// Appends `block` whole. @throws IoError naming the file and the system's reason (the file is as before).
  void append(const std::string& block);
  /// Closes the file, reporting what the system reports then. @throws IoError.
  void close();
  /// The file's size in bytes.
  std::size_t size() const { return size_; }

 private:
  std::string path_;
  int fd_ = -1;
  std::size_t size_ = 0;
};

}  // namespace ppp
