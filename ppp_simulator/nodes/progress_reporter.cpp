#include "progress_reporter.hpp"

#include <ros/console.h>

#include <chrono>
#include <utility>

namespace ppp {
namespace simulator {

ProgressReporter::ProgressReporter(const std::string& phase, const std::string& unit,
                                   std::function<std::vector<LaneCount>()> lanes)
    : meter_(phase, unit), lanes_(std::move(lanes)) {
  report();
  thread_ = std::thread([this] {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::seconds(1), [this] { return stopping_; })) report();
  });
}

ProgressReporter::~ProgressReporter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
  report();
}

void ProgressReporter::report() {
  const std::string line = meter_.update(lanes_(), steadySeconds());
  if (!line.empty()) ROS_INFO("%s", line.c_str());
}

}  // namespace simulator
}  // namespace ppp
