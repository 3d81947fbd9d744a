#include "ppp_core/progress_meter.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>

#include "ppp_core/text_format.hpp"

namespace ppp {

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string formatDuration(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char text[64];
  if (s < 60) {
    std::snprintf(text, sizeof text, "%ld s", s);
  } else if (s < 3600) {
    std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
  } else {
    const long minutes = std::lround(s / 60.0);
    std::snprintf(text, sizeof text, "%ld h %02ld min", minutes / 60, minutes % 60);
  }
  return text;
}

namespace {

/// A rate with about three significant digits, never in exponent form: 9812, 98.1, 9.81, 0.98.
std::string formatRate(double rate) { return formatFixed(rate, rate >= 100 ? 0 : rate >= 10 ? 1 : 2); }

}  // namespace

ProgressMeter::ProgressMeter(std::string phase, std::string unit, double interval_seconds)
    : phase_(std::move(phase)), unit_(std::move(unit)), interval_(interval_seconds) {}

std::string ProgressMeter::update(long done, long total, double now, const std::string& status) {
  const double elapsed = started_ ? now - start_time_ : 0.0;
  const double rate = elapsed > 0 ? static_cast<double>(done - start_done_) / elapsed : 0.0;
  const double eta = total > 0 && rate > 0 ? (total - done) / rate : -1.0;
  return line(done, total, now, total > 0 ? 100.0 * done / total : 0.0, eta, status);
}

std::string ProgressMeter::update(const std::vector<LaneCount>& lanes, double now) {
  long done = 0, total = 0;
  for (const LaneCount& lane : lanes) {
    done += lane.done;
    total += lane.total;
    auto& samples = lane_samples_[lane.name];
    samples.emplace_back(now, lane.done);
    // Keep the newest sample at least a window old as the base, and those after it.
    while (samples.size() > 2 && samples[1].first <= now - kLaneRateWindow) samples.pop_front();
  }
  const double elapsed = started_ ? now - start_time_ : 0.0;
  double eta = 0;
  const LaneCount* slowest = nullptr;
  for (const LaneCount& lane : lanes) {
    if (lane.done >= lane.total) continue;
    const auto& [base_time, base_done] = lane_samples_.at(lane.name).front();
    const long since = lane.done - base_done;
    const double left = since > 0 && now > base_time ? (lane.total - lane.done) * (now - base_time) / since : -1.0;
    if (slowest == nullptr || left < 0 || (eta >= 0 && left > eta)) {
      slowest = &lane;
      eta = left;
    }
    if (eta < 0) break;  // unknown: no lane can be slower
  }
  double percent = total > 0 ? 100.0 * done / total : 100.0;
  if (slowest != nullptr) {
    if (eta >= 0 && elapsed > 0) percent = 100.0 * elapsed / (elapsed + eta);
    percent = std::min(percent, 99.9);  // work is left: never shown as all done
  }
  std::string status;
  if (slowest != nullptr && lanes.size() > 1) {
    status = "slowest: " + slowest->name + " " + std::to_string(slowest->done) + "/" + std::to_string(slowest->total);
  }
  return line(done, total, now, percent, eta, status);
}

std::string ProgressMeter::line(long done, long total, double now, double percent, double eta,
                                const std::string& status) {
  const bool complete = total > 0 && done >= total;
  if (!started_) {
    started_ = true;
    start_time_ = now;
    start_done_ = done;
  } else if (finished_ || (!complete && now - last_line_ < interval_)) {
    return "";
  }
  last_line_ = now;
  finished_ = complete;
  const double elapsed = now - start_time_;
  const double rate = elapsed > 0 ? static_cast<double>(done - start_done_) / elapsed : 0.0;
  std::string line = "progress: " + phase_ + ": " + std::to_string(done);
  if (total > 0) {
    line += "/" + std::to_string(total) + " " + unit_ + " (" + formatFixed(percent, 1) + " %)";
  } else {
    line += " " + unit_;
  }
  if (elapsed > 0) line += ", " + formatRate(rate) + " " + unit_ + "/s";
  if (total > 0 && !complete && elapsed > 0) line += eta >= 0 ? ", ETA " + formatDuration(eta) : ", ETA unknown";
  if (complete) line += ", done in " + formatDuration(elapsed);
  if (!status.empty()) line += ", " + status;
  return line;
}

}  // namespace ppp
