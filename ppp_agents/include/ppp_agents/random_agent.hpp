#pragma once

#include "ppp_agents/agent.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace agents {

/// `random`: uniform over the five actions, drawn from its own generator. It never reads the scan (so it never
/// notices the goal either: a pure random walk, the baseline whose pass rate a Markov chain predicts exactly).
class RandomAgent final : public Agent {
 public:
  /// The memory window is accepted for uniformity and unused: the agent remembers nothing.
  explicit RandomAgent(int memory_window = 0);
  /// Reseeds the generator.
  void reset(const EpisodeInfo& info) override;
  /// A uniformly random action; the scan's window is never read.
  Action act(const Scan& scan) override;

 private:
  Rng rng_{0};
};

}  // namespace agents
}  // namespace ppp
