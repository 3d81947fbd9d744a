#include "ppp_core/append_file.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "ppp_core/error.hpp"

namespace ppp {

bool writeFully(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t written = ::write(fd, data, size);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      if (written == 0) errno = EIO;
      return false;
    }
    data += written;
    size -= static_cast<std::size_t>(written);
  }
  return true;
}

AppendFile::AppendFile(const std::string& path, bool truncate) : path_(path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | (truncate ? O_TRUNC : 0), 0666);
  if (fd_ < 0) throw IoError(path, std::string("cannot open for writing: ") + std::strerror(errno));
  struct stat info {};
  if (::fstat(fd_, &info) != 0) {
    const std::string reason = std::strerror(errno);
    ::close(fd_);
    throw IoError(path, "cannot read its size: " + reason);
  }
  size_ = static_cast<std::size_t>(info.st_size);
}

AppendFile::~AppendFile() {
  if (fd_ >= 0) ::close(fd_);
}

void AppendFile::append(const std::string& block) {
  if (fd_ < 0) throw IoError(path_, "write after close");
  if (writeFully(fd_, block.data(), block.size())) {
    size_ += block.size();
    return;
  }
  const std::string reason = std::strerror(errno);
  const bool restored = ::ftruncate(fd_, static_cast<off_t>(size_)) == 0;
  throw IoError(path_, "cannot append " + std::to_string(block.size()) + " bytes: " + reason +
                           (restored ? "" : " (and what was written of them could not be cut off again)"));
}

void AppendFile::close() {
  const int fd = fd_;
  fd_ = -1;
  if (fd >= 0 && ::close(fd) != 0) throw IoError(path_, std::string("cannot write: ") + std::strerror(errno));
}

}  // namespace ppp
