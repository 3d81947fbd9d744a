#include "ppp_core/episode_reason.hpp"

#include <initializer_list>

namespace ppp {

namespace {

/// The constant of `reasons` equal to `text`, or nullptr.
const char* reasonAmong(const std::string& text, std::initializer_list<const char*> reasons) {
  for (const char* r : reasons) {
    if (text == r) return r;
  }
  return nullptr;
}

}  // namespace

const char* reason::agentReportedReason(const std::string& text) {
  return reasonAmong(text, {kNoPath, kInvalidPath, kInvalidCommand, kPlannerTimeout, kPlannerLost, kPlannerAborted});
}

const char* reason::reasonNamed(const std::string& text) {
  return reasonAmong(text, {kGoalReached, kBudgetExhausted, kActionLimit, kTimeout, kAgentLost, kInvalidAction,
                            kNoPath, kInvalidPath, kInvalidCommand, kPlannerTimeout, kPlannerLost,
                            kPlannerAborted, kCollision, kNoProgress});
}

}  // namespace ppp
