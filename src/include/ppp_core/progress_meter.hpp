#pragma once

#include <string>

namespace ppp {

/// Seconds on a steady clock (for ProgressMeter::update; its zero is arbitrary).
double steadySeconds();

/// A duration for people: "45 s", "3 min 02 s", "2 h 05 min".
std::string formatDuration(double seconds);

/// Paces and words the progress lines of a long run whose output may be a log file: a line at the first update,
/// then at most one every `interval` seconds, and one when the work is done. A line reads
/// "progress: PHASE: DONE/TOTAL UNIT (P %), RATE UNIT/s, ETA T[, STATUS]"; with an unknown total (0) only
/// "progress: PHASE: DONE UNIT, RATE UNIT/s[, STATUS]". The rate is the mean since the first update.
class ProgressMeter {
 public:
  /// `phase` names the work ("episodes", "set 'hunted'"), `unit` what is counted ("episodes", "matings").
  ProgressMeter(std::string phase, std::string unit, double interval_seconds = 5.0);

  /// The line to show for `done` of `total` (0: unknown) at `now` (seconds on a steady clock), or "" when the
  /// last line is more recent than the interval and the work is not done.
  std::string update(long done, long total, double now, const std::string& status = "");

 private:
  std::string phase_;
  std::string unit_;
  double interval_;
  bool started_ = false;
  bool finished_ = false;
  double start_time_ = 0;
  long start_done_ = 0;
  double last_line_ = 0;
};

}  // namespace ppp
