#pragma once

#include "ppp_agents/agent.hpp"
#include "ppp_agents/agent_memory.hpp"
#include "ppp_agents/navigation.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace agents {

/// `random`: uniform over the five actions, drawn from its own generator. By its design it never reads the scan
/// (so it never notices the goal either: a pure random walk, the baseline whose pass rate a Markov chain predicts
/// exactly). With goal seeking (goal_seeking: on) it remembers its scans and, once it has noticed the goal, takes a
/// shortest path to it on that memory.
class RandomAgent final : public Agent {
 public:
  /// A random walker as its type's design: it never seeks the goal.
  RandomAgent();
  /// A random walker playing with `behaviour` (its memory is used only when it seeks the goal).
  explicit RandomAgent(const AgentBehaviour& behaviour);
  /// Reseeds the generator.
  void reset(const EpisodeInfo& info) override;
  /// A uniformly random action, or a step towards the goal once seen when seeking it.
  Action act(const Scan& scan) override;

 private:
  AgentBehaviour behaviour_;
  AgentMemory memory_;  // only when seeking the goal
  Navigator navigator_;
  Rng rng_{0};
  bool goal_seen_ = false;
};

}  // namespace agents
}  // namespace ppp
