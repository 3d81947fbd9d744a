#include "ppp_core/text_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

#include "ppp_core/append_file.hpp"
#include "ppp_core/error.hpp"

namespace ppp {

std::string readTextFile(const std::string& path, std::size_t max_bytes, const StopCheck& stop) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) throw IoError(path, std::string("cannot open: ") + std::strerror(errno));
  if (S_ISDIR(info.st_mode)) throw IoError(path, "is a directory, expected a file");
  if (static_cast<std::size_t>(info.st_size) > max_bytes) {
    throw IoError(path, "file of " + std::to_string(info.st_size) + " bytes exceeds the limit of " +
                            std::to_string(max_bytes) + " bytes");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path, std::string("cannot open: ") + std::strerror(errno));
  constexpr std::size_t kChunk = std::size_t{8} << 20;  // bytes read between two questions to `stop`
  std::string contents;
  contents.reserve(static_cast<std::size_t>(info.st_size) + kChunk);
  std::size_t used = 0;
  for (;;) {
    stopIfAsked(stop);
    contents.resize(used + kChunk);
    in.read(&contents[used], static_cast<std::streamsize>(kChunk));
    const std::size_t got = static_cast<std::size_t>(in.gcount());
    used += got;
    if (used > max_bytes) throw IoError(path, "grew beyond the limit of " + std::to_string(max_bytes) + " bytes");
    if (got < kChunk) break;
  }
  if (in.bad()) throw IoError(path, "read failed");
  contents.resize(used);
  return contents;
}

void writeFileAtomically(const std::string& path, const std::string& contents) {
  AtomicFile file(path);
  file.write(contents);
  file.commit();
}

AtomicFile::AtomicFile(const std::string& path) : path_(path), temporary_(path + ".tmp") {
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) throw IoError(path_, std::string("cannot write: ") + std::strerror(errno));
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_) std::remove(temporary_.c_str());
}

void AtomicFile::fail(const std::string& what) {
  const std::string reason = std::strerror(errno);
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::remove(temporary_.c_str());
  throw IoError(path_, what + reason);
}

void AtomicFile::write(std::string_view block) {
  if (fd_ < 0) throw IoError(path_, "write after commit");
  if (!writeFully(fd_, block.data(), block.size())) fail("cannot write: ");
}

void AtomicFile::commit() {
  if (fd_ < 0) throw IoError(path_, "committed twice");
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("cannot write: ");
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) fail("cannot replace: ");
  committed_ = true;
}

}  // namespace ppp
