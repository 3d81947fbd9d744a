#pragma once

#include "ppp_agents/continuous/continuous_agent.hpp"
#include "ppp_agents/continuous/pure_pursuit.hpp"

namespace ppp {
namespace agents {

/// The control in continuous motion: given the true map, it plans a shortest 4-connected route through the cell
/// centres of its disc's configuration space (continuousConfigurationSpace; going straight on where routes tie)
/// and follows it by pure pursuit, stopping at each turn (no corner cut). It reaches the goal of every PPP solvable for its disc.
class ContinuousAstar : public ContinuousAgent {
 public:
  void start(const ContinuousStart& start) override;
  BodyVelocity command(const ContinuousSensing& sensing) override { return follower_.command(sensing.pose, sensing.velocity); }
  bool readsLaser() const override { return false; }

 private:
  PurePursuit follower_;
};

}  // namespace agents
}  // namespace ppp
