#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_core/episode_options.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/kinematics.hpp"
#include "ppp_core/laser.hpp"
#include "ppp_core/map_frame.hpp"

namespace ppp {
namespace agents {

/// What an agent in continuous motion is told at the start of a run (never the map, but for astar, the control).
struct ContinuousStart {
  MapFrame frame;                   ///< The map's size and resolution.
  Pose2D pose;                      ///< The robot's starting pose (the start cell's centre), map frame.
  MapPoint goal;                    ///< The goal cell's centre, map frame.
  double radius = 0;                ///< The robot's radius in metres.
  KinematicLimits limits;           ///< What the robot can do.
  LaserBeams beams;                 ///< The laser's beams.
  double control_period = 0.1;      ///< Seconds each command is held.
  std::uint64_t seed = 0;           ///< Seed of the agent's own random choices.
  const Grid* prior_map = nullptr;  ///< The true map, for astar only.
};

/// What the robot senses in one control period: its exact odometry and the laser.
struct ContinuousSensing {
  Pose2D pose;                     ///< Map-frame pose.
  BodyVelocity velocity;           ///< Velocity during the last period, robot frame.
  double time = 0;                 ///< Simulated seconds since the start.
  const std::vector<float>* ranges = nullptr;  ///< Laser ranges (+inf: no return), beam order of ContinuousStart.
};

/// An agent that drives the robot in continuous motion: a velocity command per control period.
class ContinuousAgent {
 public:
  virtual ~ContinuousAgent() = default;
  /// Called once at the start of each run.
  virtual void start(const ContinuousStart& start) = 0;
  /// The command for this period.
  virtual BodyVelocity command(const ContinuousSensing& sensing) = 0;
  /// True when the agent reads the laser (else the runner does not cast it).
  virtual bool readsLaser() const = 0;
};

/// @throws InvalidArgument naming "motion" when `config` plays in continuous motion under `options` but moves
/// only on the grid (every built-in type but astar).
void checkContinuousAgent(const AgentConfig& config, const EpisodeOptions& options);

/// For what plays the grid model only (the grid runner and its lanes, hunts and shrinks of built-in agents):
/// @throws InvalidArgument naming "motion" when `config` plays in continuous motion under `options`.
void refuseContinuous(const AgentConfig& config, const EpisodeOptions& options);

/// True when a built-in agent of `config`'s type can move in continuous motion (astar).
bool movesContinuously(const AgentConfig& config);

/// The continuous agent of `config`. @throws InvalidArgument naming "motion" for an agent that moves only on the
/// grid.
std::unique_ptr<ContinuousAgent> makeContinuousAgent(const AgentConfig& config);

}  // namespace agents
}  // namespace ppp
