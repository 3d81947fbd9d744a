#pragma once

#include <deque>
#include <map>
#include <string>
#include <vector>

namespace ppp {

/// Seconds on a steady clock (for ProgressMeter::update; its zero is arbitrary).
double steadySeconds();

/// A duration for people: "45 s", "3 min 02 s", "2 h 05 min".
std::string formatDuration(double seconds);

/// What one of several lanes of work played side by side has done: its name (an agent's), units done and in all.
struct LaneCount {
  std::string name;
  long done = 0;
  long total = 0;
};

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

  /// The same for lanes played side by side whose units cost different times (a grid agent's episodes and a ROS
  /// planner's in continuous motion): DONE and TOTAL are the lanes' sums, but the share and the ETA are of the
  /// time, the slowest unfinished lane's at its own recent rate (over the last kLaneRateWindow seconds of updates,
  /// so a lane that waited for the others' cores is judged by its pace once they are done), and that lane is named
  /// with its counts ("slowest: NAME d/t"). The share reads 100 % only when every lane is done; while a lane that
  /// has work left has done none over that window, the ETA is unknown and the share is of the units, below 100 %.
  std::string update(const std::vector<LaneCount>& lanes, double now);

 private:
  /// The line for `done` of `total` at `now` (pacing as update()): `percent` the share to show, `eta` the seconds
  /// left (negative: unknown), `status` what follows.
  std::string line(long done, long total, double now, double percent, double eta, const std::string& status);

  std::string phase_;
  std::string unit_;
  double interval_;
  bool started_ = false;
  bool finished_ = false;
  double start_time_ = 0;
  long start_done_ = 0;
  double last_line_ = 0;
  /// Each lane's (seconds, units done) at every update since kLaneRateWindow before the last one.
  std::map<std::string, std::deque<std::pair<double, long>>> lane_samples_;
};

/// Seconds of a lane's recent updates its rate is reckoned over (ProgressMeter::update of lanes).
constexpr double kLaneRateWindow = 30.0;

}  // namespace ppp
