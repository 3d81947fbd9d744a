#include "stop_signals.hpp"

#include <atomic>
#include <csignal>

namespace ppp {
namespace cli {

namespace {

std::atomic<bool> stop_requested{false};

extern "C" void requestStop(int) { stop_requested.store(true); }

}  // namespace

StopCheck stopOnSignals() {
  std::signal(SIGINT, requestStop);
  std::signal(SIGTERM, requestStop);
  return [] { return stop_requested.load(std::memory_order_relaxed); };
}

}  // namespace cli
}  // namespace ppp
