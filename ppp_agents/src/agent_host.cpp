#include "ppp_agents/agent_host.hpp"

#include <string>

#include "ppp_core/error.hpp"

namespace ppp {
namespace agents {

AgentHost::AgentHost(const AgentConfig& config) : config_(config) { config_.validate(); }

Agent& AgentHost::start(std::uint32_t id, const EpisodeInfo& info, const Grid* prior_map) {
  finish(id);
  Slot slot;
  if (!idle_.empty()) {
    slot = std::move(idle_.back());
    idle_.pop_back();
  } else {
    slot.agent = makeAgent(config_);
  }
  EpisodeInfo episode = info;
  slot.prior_map = prior_map != nullptr ? std::make_unique<Grid>(*prior_map) : nullptr;
  episode.prior_map = slot.prior_map.get();
  try {
    slot.agent->reset(episode);
  } catch (...) {  // the agent refuses the episode: back to the pool, not destroyed
    slot.prior_map.reset();
    idle_.push_back(std::move(slot));
    throw;
  }
  Slot& stored = active_[id] = std::move(slot);
  return *stored.agent;
}

Action AgentHost::act(std::uint32_t id, const Scan& scan) {
  const auto it = active_.find(id);
  if (it == active_.end()) throw InvalidArgument("episode", "episode " + std::to_string(id) + " was never started");
  return it->second.agent->act(scan);
}

void AgentHost::finish(std::uint32_t id) {
  const auto it = active_.find(id);
  if (it == active_.end()) return;
  it->second.prior_map.reset();
  idle_.push_back(std::move(it->second));
  active_.erase(it);
}

}  // namespace agents
}  // namespace ppp
