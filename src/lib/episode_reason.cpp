#include "ppp_core/episode_reason.hpp"

namespace ppp {

const char* reason::agentReportedReason(const std::string& text) {
  for (const char* r : {kNoPath, kInvalidPath, kPlannerTimeout, kPlannerLost}) {
    if (text == r) return r;
  }
  return nullptr;
}

}  // namespace ppp
