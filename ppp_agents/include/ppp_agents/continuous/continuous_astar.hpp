#pragma once

#include <vector>

#include "ppp_agents/continuous/continuous_agent.hpp"
#include "ppp_agents/continuous/pure_pursuit.hpp"

namespace ppp {
namespace agents {

/// A shortest 4-connected route through the cell centres of the configuration space of a disc of `radius` metres
/// on `map` (continuousConfigurationSpace), from the cell holding `from` to the cell holding `to` (map frame),
/// going straight on where routes tie: the centres in order, empty when there is none.
std::vector<MapPoint> centreRoute(const Grid& map, const MapFrame& frame, double radius, MapPoint from, MapPoint to);

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
