#include "ppp_simulator/report/motion_models.hpp"

#include <algorithm>
#include <utility>

#include "ppp_agents/continuous/continuous_agent.hpp"
#include "ppp_core/diagnosis.hpp"

namespace ppp {
namespace simulator {

std::vector<MotionPair> motionPairs(const std::vector<agents::AgentConfig>& agents, const EpisodeOptions& episode) {
  std::vector<MotionPair> pairs;
  for (const agents::AgentConfig& moving : agents) {
    if (!agents::playsContinuously(moving, episode)) continue;
    const auto onGrid = [&](bool same_args) {
      return std::find_if(agents.begin(), agents.end(), [&](const agents::AgentConfig& a) {
        return !agents::playsContinuously(a, episode) && a.type == moving.type && a.planner_node == moving.planner_node &&
               (!same_args || a.planner_args == moving.planner_args);
      });
    };
    auto same = onGrid(true);
    if (same == agents.end()) same = onGrid(false);
    if (same != agents.end()) pairs.push_back({same->name, moving.name});
  }
  return pairs;
}

std::string failureKinds(const SetPassRate& row) {
  std::vector<std::pair<int, std::string>> counts;
  for (int k = 0; k < diagnosis::kKindCount; ++k) {
    const std::string kind = diagnosis::kKinds[k];
    if (kind == diagnosis::kDetour) continue;  // a passed run's
    int n = row.diagnoses.kinds[static_cast<std::size_t>(k)];
    if (kind == diagnosis::kReported) {
      if (row.diagnoses.collisions > 0) counts.push_back({row.diagnoses.collisions, "collision"});
      n -= row.diagnoses.collisions;
    }
    if (n > 0) counts.push_back({n, kind});
  }
  std::stable_sort(counts.begin(), counts.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::string text;
  for (const auto& [n, kind] : counts) text += (text.empty() ? "" : ", ") + std::to_string(n) + " " + kind;
  return text.empty() ? "none" : text;
}

}  // namespace simulator
}  // namespace ppp
