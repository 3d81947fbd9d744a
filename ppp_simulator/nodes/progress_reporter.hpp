#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "ppp_core/progress_meter.hpp"

namespace ppp {
namespace simulator {

/// Logs a ProgressMeter line (ROS_INFO) every few seconds while work runs in other threads: it reads the count
/// done from `done` each second, and the last line when it is destroyed.
class ProgressReporter {
 public:
  /// Starts reporting `total` units of `unit` for `phase` (ProgressMeter's words).
  ProgressReporter(const std::string& phase, const std::string& unit, long total, std::function<long()> done);
  /// Stops the thread after a last line (the end, when everything was done).
  ~ProgressReporter();

  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

 private:
  void report();

  ProgressMeter meter_;
  long total_;
  std::function<long()> done_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace simulator
}  // namespace ppp
