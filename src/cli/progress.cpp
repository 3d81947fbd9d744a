#include "progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <utility>

namespace ppp {
namespace cli {

Progress::Progress(std::string label, bool quiet)
    : label_(std::move(label)), quiet_(quiet), terminal_(::isatty(STDERR_FILENO) != 0) {}

void Progress::update(long done, long total, const std::string& status) {
  if (quiet_) return;
  const double fraction = total > 0 ? static_cast<double>(done) / total : 1.0;
  if (terminal_) {
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth);
    std::fprintf(stderr, "\r[%-*s] %ld/%ld %s, %s", kWidth, std::string(filled, '#').c_str(), done, total,
                 label_.c_str(), status.c_str());
    if (done >= total) std::fprintf(stderr, "\n");
    std::fflush(stderr);
    return;
  }
  const long tenth = static_cast<long>(fraction * 10);
  if (tenth == last_tenth_) return;
  last_tenth_ = tenth;
  std::fprintf(stderr, "%3d%% %ld/%ld %s, %s\n", static_cast<int>(fraction * 100), done, total, label_.c_str(),
               status.c_str());
}

}  // namespace cli
}  // namespace ppp
