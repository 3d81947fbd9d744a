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
  const std::string temporary = path + ".tmp";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw IoError(path, std::string("cannot write: ") + std::strerror(errno));
  int error = writeFully(fd, contents.data(), contents.size()) ? 0 : errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error == 0) {
    if (std::rename(temporary.c_str(), path.c_str()) == 0) return;
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw IoError(path, "cannot replace: " + reason);
  }
  std::remove(temporary.c_str());
  throw IoError(path, std::string("cannot write: ") + std::strerror(error));
}

}  // namespace ppp
