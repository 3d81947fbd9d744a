#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "ppp_core/progress_meter.hpp"

namespace ppp {
namespace simulator {

/// Logs a ProgressMeter line (ROS_INFO) every few seconds while work runs in other threads: it reads the lanes'
/// counts from `lanes` each second, and the last line when it is destroyed.
class ProgressReporter {
 public:
  /// Starts reporting the units of `unit` done by lanes side by side for `phase` (ProgressMeter's words).
  ProgressReporter(const std::string& phase, const std::string& unit, std::function<std::vector<LaneCount>()> lanes);
  /// Stops the thread after a last line (the end, when everything was done).
  ~ProgressReporter();

  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

 private:
  void report();

  ProgressMeter meter_;
  std::function<std::vector<LaneCount>()> lanes_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace simulator
}  // namespace ppp
