#include "ppp_core/episode_reason.hpp"

namespace ppp {

const char* reason::agentReportedReason(const std::string& text) {
  for (const char* r : {kNoPath, kInvalidPath, kPlannerTimeout, kPlannerLost}) {
    if (text == r) return r;
  }
  return nullptr;
}

const char* reason::reasonNamed(const std::string& text) {
  for (const char* r : {kGoalReached, kBudgetExhausted, kTimeout, kAgentLost, kInvalidAction, kNoPath, kInvalidPath,
                        kPlannerTimeout, kPlannerLost, kCollision}) {
    if (text == r) return r;
  }
  return nullptr;
}

}  // namespace ppp
