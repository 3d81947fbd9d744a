#pragma once

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "planner_bridge_parameters.hpp"
#include "planner_link.hpp"
#include "ppp_agents/protocol/continuous_codec.hpp"
#include "ppp_msgs/SensingBatch.h"

namespace ppp {
namespace agents {

/// Plays a planner agent in continuous motion (interface cmd_vel): for each control period of the simulator's
/// episode (a SensingBatch of one episode) it publishes the robot's world to the planner at the period's simulated
/// time (tf map -> odom -> base_link, odom with pose and twist, the laser, the goal as the period's request, and
/// robot/clock, which the planner reads as /clock with /use_sim_time set), waits for the planner's velocity command stamped at that time or later, and
/// answers the simulator with it (the simulator's base controller clamps it), or with the failure planner_timeout
/// or planner_lost. Each episode's clock starts a second after the last one's end, so the planner's time never runs
/// backwards. Periods are played in a thread of the bridge's own, which may wait for the planner.
class ContinuousPlannerBridge {
 public:
  /// Talks to the planner through `link` (PlannerBridge's).
  ContinuousPlannerBridge(PlannerLink* link, const BridgeParameters& parameters);
  ~ContinuousPlannerBridge();
  /// Connects to the simulator in `nh`'s namespace (sensing in, commands out).
  void serve(ros::NodeHandle& nh);

 private:
  void onSensing(const ppp_msgs::SensingBatch::ConstPtr& batch);
  /// The reply to the batch's one episode: its command, or a failure reason.
  agents::ContinuousReply step(const ppp_msgs::SensingBatch& batch);
  void warnOnce(const std::string& kind, const std::string& text);

  PlannerLink& link_;
  BridgeParameters parameters_;
  ros::CallbackQueue queue_;  // the sensing's: played by spinner_, which may wait for the planner
  ros::AsyncSpinner spinner_;
  ros::Publisher commands_;
  ros::Subscriber sensing_;

  std::optional<protocol::DecodedStart> episode_;  // the episode being played
  std::uint32_t episode_id_ = 0;
  ros::Time origin_;      // the simulated time of the episode's start
  ros::Time last_stamp_;  // the latest time published
  std::map<std::string, long> warnings_;
};

}  // namespace agents
}  // namespace ppp
