#pragma once

#include <ros/ros.h>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>

#include "geometry_msgs/TwistStamped.h"
#include "std_msgs/Header.h"
#include "nav_msgs/Path.h"
#include "planner_bridge_parameters.hpp"
#include "ppp_agents/planner_episode.hpp"
#include "ppp_core/kinematics.hpp"
#include "ppp_core/laser.hpp"
#include "ppp_msgs/lockstep_queue.h"

namespace ppp {
namespace agents {

/// The answers of one message type a planner sent (paths or velocity commands), as roscpp's network thread reads
/// them: the newest, and how many came and were looked at.
template <class Message>
struct AnswerInbox {
  std::mutex mutex;
  std::condition_variable arrived;
  std::optional<Message> latest;
  std::uint64_t received = 0;
  std::uint64_t used = 0;
  /// Keeps `answer` as the newest and wakes a wait for it.
  void put(const Message& answer) {
    std::lock_guard<std::mutex> lock(mutex);
    latest = answer;
    ++received;
    arrived.notify_one();
  }
  /// Marks every answer received so far as looked at.
  void skipReceived() {
    std::lock_guard<std::mutex> lock(mutex);
    used = received;
  }
};

/// A local planner's answer to a request: a velocity command, or its giving up on the goal.
struct VelocityAnswer {
  std_msgs::Header header;                ///< The command's; when aborted, stamped with the status's goal_id.stamp.
  geometry_msgs::TwistStamped command;    ///< The command, unless aborted.
  std::optional<std::string> aborted;     ///< When the planner gave up (a status ABORTED): its text.
};

/// The planner bridge's side towards the external planner (docs/reference/planner-interface.md): publishes what the robot
/// knows (map, odom, tf, scan) and plan requests (goal) in robot/..., and takes the planner's answers (paths on
/// `plan`, or velocity commands on `cmd_vel` as the bridge's `interface` says) on a callback queue of its own, so
/// that a step can wait for one. It publishes handing over (ppp_msgs/hand_over.h): a planner nodelet of the same
/// manager answers in the publishing thread, and its answer is in before the publish returns.
class PlannerLink {
 public:
  /// Advertises and subscribes in `nh`'s robot/ namespace; answers are read in roscpp's network thread
  /// (`in_network_thread`: a process of its own) or as ppp_msgs::LockstepQueue reads them for a nodelet.
  PlannerLink(ros::NodeHandle& nh, const BridgeParameters& parameters, bool in_network_thread);
  /// Waits up to connect_timeout for the planner to subscribe to the goal and publish its answer topic.
  /// @return false when stop() or ROS's shutdown ended the wait.
  /// @throws InvalidArgument naming each topic that is missing or has the wrong type.
  bool waitForPlanner();
  /// Ends waitForPlanner() and any wait for an answer within 50 ms: the node is going.
  void stop() { stopping_ = true; }
  /// The planner-side topic names, for the log.
  std::string topics() const;
  /// Publishes the robot's world at `stamp`: the episode's known map (its map_load_time `episode_stamp`, the stamp
  /// of the episode's first step, so a planner with memory of its own sees a new episode start), then
  /// publishPose's messages.
  void publishState(const ros::Time& stamp, const ros::Time& episode_stamp, const PlannerEpisode& episode,
                    Cell robot, const std::int8_t* window, int range);
  /// Publishes the robot's pose at `stamp` (tf and odom) and its scan.
  void publishPose(const ros::Time& stamp, const PlannerEpisode& episode, Cell robot, const std::int8_t* window,
                   int range);
  /// Publishes a plan request: the episode's goal, stamped `stamp`.
  void publishGoal(const ros::Time& stamp, const PlannerEpisode& episode);
  /// Continuous motion: publishes the robot's map `cells` (grid order, kScan... values) of `frame`'s size, stamped
  /// `stamp`, loaded at `episode_stamp` (the episode's start, so a planner with memory of its own sees a new one).
  void publishContinuousMap(const ros::Time& stamp, const ros::Time& episode_stamp, const MapFrame& frame,
                            const std::vector<std::int8_t>& cells);
  /// Continuous motion: publishes one control period at the simulated time `stamp`: tf odom -> base_link (map ->
  /// odom is publishOdometryFrame's), the odometry (`pose` and `velocity`), the laser's `ranges`, the
  /// request if any (the goal, map frame), then the clock at `stamp` (last, so a planner whose timer fires on it
  /// has the period's messages, which it can tell by their stamp).
  void publishContinuous(const ros::Time& stamp, const Pose2D& pose, const BodyVelocity& velocity,
                         const std::vector<float>& ranges, const LaserBeams& beams,
                         const std::optional<MapPoint>& request);
  /// Continuous motion: publishes the static tf map -> odom (latched; continuous motion's odometry is exact).
  void publishOdometryFrame();
  /// Continuous motion: publishes the planner's clock at `stamp` (latched).
  void publishClock(const ros::Time& stamp);
  /// A new episode: paths sent so far answer an earlier one, and the planner has not answered in this one.
  void newEpisode();
  /// The newest path the planner published on its own since the last look, if any.
  std::optional<nav_msgs::Path> takeUnasked();
  /// Waits up to plan_timeout for a path stamped at or after `request` (or unstamped, unless lockstep) that
  /// `fits`; a path that does not fit is kept and returned when no better one comes. `resend()` sends the
  /// request again every second (a restarted planner missed it). Marks the planner as having answered when a path
  /// is returned.
  std::optional<nav_msgs::Path> waitForPath(const ros::Time& request,
                                            const std::function<bool(const nav_msgs::Path&)>& fits,
                                            const std::function<void()>& resend);
  /// Waits up to plan_timeout for a velocity command stamped at or after `request`, or a status ABORTED on
  /// planner_status for such a goal stamp, as waitForPath waits for a path (every command fits).
  std::optional<VelocityAnswer> waitForCommand(const ros::Time& request,
                                               const std::function<void()>& resend);
  /// True when the planner that answered in this episode is gone: disconnected, or its process dead
  /// (asked over XML-RPC at most every 0.2 s).
  bool gone();
  /// True when a planner is connected and its process answers.
  bool alive() const;
  /// True when the last wait for an answer ended because the planner that answered in this episode was gone (even
  /// if a restarted one is connected by now).
  bool lostWhileWaiting() const { return lost_; }

 private:
  /// interface cmd_vel: subscribes to the planner's commands and its statuses (planner_link_velocity.cpp).
  void subscribeVelocityAnswers();
  template <class Message>
  std::optional<Message> waitFor(AnswerInbox<Message>* inbox, const ros::Time& request,
                                 const std::function<bool(const Message&)>& fits,
                                 const std::function<void()>& resend);
  bool connected() const { return answers_.getNumPublishers() > 0; }
  /// The answer topic's type, as the master names it.
  const char* answerType() const;

  /// True while the node runs (ROS is up and stop() was not called).
  bool running() const { return ros::ok() && !stopping_; }

  BridgeParameters parameters_;
  std::atomic<bool> stopping_{false};
  ros::NodeHandle nh_;  // robot/...
  ros::Publisher map_, odom_, scan_, goal_, clock_;
  ros::Publisher tf_;         // /tf as the node's remappings name it (a nodelet's too)
  ros::Publisher tf_static_;  // /tf_static likewise
  ppp_msgs::LockstepQueue queue_;  // the answer subscription's
  ros::Subscriber answers_;  // plan or cmd_vel
  ros::Subscriber statuses_;  // planner_status, with cmd_vel
  bool answered_ = false;     // the planner sent a path during this episode
  bool lost_ = false;         // the last wait ended with the planner gone
  ros::WallTime next_probe_;  // when gone() may ask the planner's process again

  // Answers from the planner (written on the queue's thread): one inbox is used, as `interface` says.
  AnswerInbox<nav_msgs::Path> paths_;
  AnswerInbox<VelocityAnswer> commands_;  // commands and statuses ABORTED
};

}  // namespace agents
}  // namespace ppp
