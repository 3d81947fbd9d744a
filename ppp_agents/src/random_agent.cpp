#include "ppp_agents/random_agent.hpp"

namespace ppp {
namespace agents {

RandomAgent::RandomAgent() { behaviour_.seek_goal = false; }

RandomAgent::RandomAgent(const AgentBehaviour& behaviour) : behaviour_(behaviour) {}

void RandomAgent::reset(const EpisodeInfo& info) {
  rng_ = Rng(info.seed);
  goal_seen_ = false;
  if (behaviour_.seek_goal) {
    memory_.reset(info.width, info.height, behaviour_.memory_window, behaviour_.memory_scans);
    navigator_.reset(info.width, info.height);
  }
}

Action RandomAgent::act(const Scan& scan) {
  if (behaviour_.seek_goal) {
    memory_.update(scan);
    Action action;
    if (navigator_.towardsSeenGoal(scan, memory_, behaviour_.goal_range, &goal_seen_, &action)) return action;
  }
  return static_cast<Action>(rng_.below(kActionCount));
}

}  // namespace agents
}  // namespace ppp
