#pragma once

#include <string>

namespace ppp {
namespace cli {

/// Shows the progress of a long run on stderr: a redrawn bar on a terminal, a log line every
/// tenth of the run otherwise (so CI logs and pipes stay readable).
class Progress {
 public:
  /// `label` names the work, e.g. "matings"; nothing is shown when `quiet`.
  Progress(std::string label, bool quiet);
  /// Reports `done` of `total`, with a short status text such as "best 12".
  void update(long done, long total, const std::string& status);

 private:
  std::string label_;
  bool quiet_;
  bool terminal_;
  long last_tenth_ = -1;
};

}  // namespace cli
}  // namespace ppp
