#include "ppp_agents/random_agent.hpp"

namespace ppp {
namespace agents {

RandomAgent::RandomAgent(int /*memory_window*/) {}

void RandomAgent::reset(const EpisodeInfo& info) { rng_ = Rng(info.seed); }

Action RandomAgent::act(const Scan& /*scan*/) { return static_cast<Action>(rng_.below(kActionCount)); }

}  // namespace agents
}  // namespace ppp
