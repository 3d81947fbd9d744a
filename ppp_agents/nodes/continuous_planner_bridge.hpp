#pragma once

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planner_bridge_parameters.hpp"
#include "planner_link.hpp"
#include "ppp_agents/continuous/plan_follower.hpp"
#include "ppp_agents/protocol/continuous_codec.hpp"
#include "ppp_msgs/SensingBatch.h"
#include "ppp_msgs/lockstep_queue.h"

namespace ppp {
namespace agents {

/// Plays a planner agent in continuous motion: for each control period of the simulator's episode (a SensingBatch
/// of one episode) it publishes the robot's world to the planner at the period's simulated time (tf map -> odom ->
/// base_link, odom with pose and twist, the laser, and robot/clock, which the planner reads as /clock with
/// /use_sim_time set) and answers the simulator with a velocity command (the simulator's base controller clamps
/// it), or with a failure (planner_timeout, planner_lost, ...):
/// - interface cmd_vel: every period is a request; the episode's map and goal go with each period
///   (period_messages every) or with its first (changes); the command is the planner's, stamped at that time or
///   later;
/// - interface path: a PlanFollower says which periods are requests (plan_requests); a request publishes the
///   robot's map (the true one, or the one its laser built) and the goal and waits for the planner's path; the
///   command follows the path taken by pure pursuit.
/// Each episode's clock starts a second (or two control periods, when longer) after the last one's end, so the
/// planner's time never runs backwards and an episode's first period never comes one control period after another.
/// A nodelet plays each period in the simulator's thread that handed it over (a planner nodelet of the same manager
/// answers there too: no thread wakes for a period); a process of its own plays them in a thread of its own, which
/// may wait for the planner while roscpp's network thread reads its answer.
class ContinuousPlannerBridge {
 public:
  /// Talks to the planner through `link` (PlannerBridge's); `in_network_thread`: a process of its own.
  ContinuousPlannerBridge(PlannerLink* link, const BridgeParameters& parameters, bool in_network_thread);
  ~ContinuousPlannerBridge();
  /// Connects to the simulator in `nh`'s namespace (sensing in, commands out).
  void serve(ros::NodeHandle& nh);

 private:
  void onSensing(const ppp_msgs::SensingBatch::ConstPtr& batch);
  /// The reply to the batch's one episode: its command, or a failure reason.
  agents::ContinuousReply step(const ppp_msgs::SensingBatch& batch);
  /// Publishes the period `sensing` at `stamp`, with the goal when it is a `request`.
  void publish(const ros::Time& stamp, const ContinuousSensing& sensing, bool request);
  /// interface cmd_vel: the planner's command for the period into `reply`, or its failure; each time the planner
  /// leaves the period unanswered for a wall second it is asked again: a control period later when a timer wakes the
  /// planner (wakes_on), as it was when its messages do.
  void command(const ros::Time& stamp, const ContinuousSensing& sensing, ContinuousReply* reply);
  /// interface path: the command along the planner's path into `reply`, asking for one when the period is a
  /// request, or the failure.
  void followPlans(const ros::Time& stamp, const ContinuousSensing& sensing, ContinuousReply* reply);
  /// Why a wait for the planner's answer ended without one: planner_lost when the planner was gone, else
  /// planner_timeout.
  const char* silentPlannerFailure();
  void warnOnce(const std::string& kind, const std::string& text);

  PlannerLink& link_;
  BridgeParameters parameters_;
  ros::CallbackQueue own_queue_;  // a process's sensing: played by spinner_, which may wait for the planner
  ros::AsyncSpinner spinner_;
  std::unique_ptr<ppp_msgs::LockstepQueue> handed_over_;  // a nodelet's sensing, played where it is handed over
  ros::Publisher commands_;
  ros::Subscriber sensing_;

  std::optional<protocol::DecodedStart> episode_;  // the episode being played
  PlanFollower plans_;                             // interface path: the robot's map, requests and path
  std::uint32_t episode_id_ = 0;
  ros::Time origin_;         // the simulated time of the episode's start, moved on by each period asked again
  ros::Time episode_start_;  // the simulated time of the episode's start: its map's map_load_time
  ros::Time first_period_;   // the stamp of the episode's first period (period_messages changes: its map and goal)
  std::vector<std::int8_t> start_map_;  // what the robot knows at the start (kScan... values, the frame's cells)
  ros::Time last_stamp_;  // the latest time published
  std::map<std::string, long> warnings_;
};

}  // namespace agents
}  // namespace ppp
