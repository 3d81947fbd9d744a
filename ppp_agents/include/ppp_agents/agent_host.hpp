#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "ppp_agents/agent.hpp"
#include "ppp_agents/agent_config.hpp"
#include "ppp_core/grid.hpp"

namespace ppp {
namespace agents {

/// Hosts one agent instance per episode of a batch, for an agent process serving many episodes at once.
/// Instances are reused when episodes end, so a long experiment creates only batch-size agents.
class AgentHost {
 public:
  /// Agents of one configuration. @throws InvalidArgument for a bad configuration.
  explicit AgentHost(const AgentConfig& config);
  /// Starts episode `id`: a fresh (reset) agent; `prior_map` is kept for the episode when not empty. Returns
  /// the episode's agent, valid until the episode is finished (callers may act on it directly).
  /// @throws InvalidArgument when the agent refuses the episode (astar without a prior map); episode `id` is then
  /// not hosted (a restarted id's earlier episode is over) and the agent stays in the pool.
  Agent& start(std::uint32_t id, const EpisodeInfo& info, const Grid* prior_map);
  /// The action of episode `id` for this scan. @throws InvalidArgument for an episode never started.
  Action act(std::uint32_t id, const Scan& scan);
  /// Ends episode `id` and frees its agent for reuse (unknown ids are ignored).
  void finish(std::uint32_t id);
  /// Episodes currently hosted.
  std::size_t active() const { return active_.size(); }

 private:
  struct Slot {
    std::unique_ptr<Agent> agent;
    std::unique_ptr<Grid> prior_map;
  };
  AgentConfig config_;
  std::map<std::uint32_t, Slot> active_;
  std::vector<Slot> idle_;
};

}  // namespace agents
}  // namespace ppp
