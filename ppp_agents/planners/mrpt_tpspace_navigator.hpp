#pragma once

#include <future>
#include <memory>
#include <string>
#include <vector>

#include "ppp_core/kinematics.hpp"
#include "ppp_core/map_frame.hpp"

namespace mrpt::config {
class CConfigFileMemory;
}  // namespace mrpt::config
namespace mrpt::nav {
class CReactiveNavigationSystem;
}  // namespace mrpt::nav

namespace ppp {
namespace planners {

/// The differential-drive robot the TP-space navigator drives.
struct TpSpaceRobot {
  double radius = 0;             ///< Metres; its shape is a regular 16-gon around this disc.
  double max_linear_speed = 0;   ///< m/s.
  double max_angular_speed = 0;  ///< rad/s.
};

/// One control period as the navigator senses it.
struct TpSpaceSensing {
  double time = 0;                 ///< Simulated seconds since the episode's start (MRPT's clock is set to it).
  Pose2D pose;                     ///< The robot's pose, map frame (odometry is exact).
  BodyVelocity velocity;           ///< Its velocity, robot frame.
  std::vector<MapPoint> returns;   ///< The laser's returns, robot frame, metres.
};

/// The returns of a laser scan (`ranges` in metres from `angle_min`, `angle_increment` apart) as points in the
/// robot's frame; a range that is not finite (no return, or no reading) is none.
std::vector<MapPoint> laserReturns(const std::vector<float>& ranges, double angle_min, double angle_increment);

/// MRPT's TP-space reactive navigator (mrpt::nav::CReactiveNavigationSystem), driven one navigationStep per control
/// period on simulated time: it reads the robot's pose, velocity and laser returns, and sends a differential-drive
/// velocity command. Its options are an MRPT reactive navigation configuration (INI text: PTGs, holonomic method,
/// motion decider); the robot's limits and shape replace the configuration's own (robotMax_V_mps,
/// robotMax_W_degps, each PTG's v_max_mps and w_max_dps, the shape), so the navigator knows the robot it drives.
/// Only one navigator per process: MRPT's clock is the process's.
class MrptTpSpaceNavigator {
 public:
  /// @throws InvalidArgument naming robot_radius, max_linear_speed or max_angular_speed when not positive, or
  ///         `source` (the configuration's file name) with MRPT's complaint when MRPT refuses the configuration.
  MrptTpSpaceNavigator(const std::string& config_text, const std::string& source, const TpSpaceRobot& robot);
  ~MrptTpSpaceNavigator();

  /// Starts navigating to `goal` (map frame), arriving within `tolerance` metres, with a navigator that has never
  /// navigated. Making one takes MRPT a second or two (it simulates its trajectories again), too long for a
  /// period's answer: the next episode's is made in the background while this one plays.
  /// @throws Error with MRPT's message when MRPT fails to make it.
  void start(MapPoint goal, double tolerance);
  /// One navigation step for the period `sensing`: the command (linear x, angular z).
  /// @throws Error with MRPT's message when the navigator fails.
  BodyVelocity step(const TpSpaceSensing& sensing);
  /// Why the navigator stopped navigating ("" while it navigates or after it arrived).
  std::string error() const;

 private:
  /// A new navigator from the configuration. Touches nothing but the configuration, the robot interface's address
  /// and the cache directory, so it may run beside a navigator's steps.
  std::unique_ptr<mrpt::nav::CReactiveNavigationSystem> build() const;

  class Robot;
  struct CacheDirectory;
  std::unique_ptr<Robot> robot_;
  double radius_;
  std::unique_ptr<CacheDirectory> cache_;  // the PTGs' collision grids, built by the first navigator
  std::unique_ptr<mrpt::config::CConfigFileMemory> config_;
  std::unique_ptr<mrpt::nav::CReactiveNavigationSystem> navigator_;
  bool navigated_ = false;  // navigator_ has had a target
  std::future<std::unique_ptr<mrpt::nav::CReactiveNavigationSystem>> next_;  // last: waited for first on destruction
};

}  // namespace planners
}  // namespace ppp
