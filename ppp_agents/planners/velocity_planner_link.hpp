#pragma once

// What every example local planner node shares: it takes the robot's scan, odometry, map and goal as the planner
// bridge publishes them, matches them by stamp and answers each request with one velocity command
// (docs/reference/planner-interface.md, "Velocity commands"):
//   subscribes  scan (sensor_msgs/LaserScan)                the robot's scan, in its frame
//               odom (nav_msgs/Odometry)                   the robot's pose (frame ~map_frame, child ~base_frame)
//               map (nav_msgs/OccupancyGrid)               what the robot knows; a new map_load_time starts a new
//                                                          episode
//               move_base_simple/goal (geometry_msgs/PoseStamped)  on the grid a request, answered once the scan,
//                                                          pose and map of its stamp are in; in continuous motion
//                                                          the episode's goal, sent with every period or with its
//                                                          first (the bridge's period_messages)
//   publishes   cmd_vel (geometry_msgs/TwistStamped)       on the grid stamped with the goal's stamp; in continuous
//                                                          motion one command per control period, stamped with its
//                                                          scan's, as soon as the scan and odometry of its stamp are
//                                                          in, and, when it begins an episode (it does not come one
//                                                          control period after the last one answered), the goal
//                                                          and map of its stamp
//               planner_status (actionlib_msgs/GoalStatus) instead of the command when the node gives up on its
//                                                          goal: ABORTED, its goal_id stamped as the command would
//                                                          be, the reason as text
// Topics are relative: the node runs in the bridge's robot namespace (/G/robot).

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>

#include <deque>
#include <functional>
#include <mutex>
#include <string>

#include "planner_node_options.hpp"
#include "ppp_core/error.hpp"
#include "ppp_msgs/lockstep_queue.h"

namespace ppp {
namespace planners {

/// One request of a local planner: the robot's scan and odometry of one step or period, its goal.
struct VelocityRequest {
  const sensor_msgs::LaserScan& scan;
  const nav_msgs::Odometry& pose;
  const geometry_msgs::PoseStamped& goal;
  const nav_msgs::OccupancyGrid& map;
  bool new_episode;  ///< The first request of an episode (the map's map_load_time changed).
};

/// Thrown by a node's answer when it gives up on its goal: the link answers with a status ABORTED whose text is the
/// message, and the run ends as planner_aborted.
class GoalAbandoned : public Error {
 public:
  using Error::Error;
};

/// The lockstep plumbing of a local planner node; the node says how it answers.
class VelocityPlannerLink {
 public:
  /// The command for a request; GoalAbandoned thrown gives up on the goal, another Error leaves the robot standing
  /// (logged).
  using Answer = std::function<geometry_msgs::Twist(const VelocityRequest&)>;

  /// Subscribes in `nh`'s namespace. `control_period` > 0: the robot moves continuously, a period every so many
  /// seconds (the periods ask, not goals); 0: the grid.
  VelocityPlannerLink(ros::NodeHandle& nh, const PlannerFrames& frames, double control_period,
                      bool in_network_thread, Answer answer);

  /// "scan, odom, map, goal -> cmd_vel" with their resolved names, for the node's start-up line.
  std::string topics() const;

 private:
  /// True when the robot moves continuously (a control period was given), false on the grid.
  bool continuous() const { return control_period_ > ros::Duration(0); }
  void onScan(const sensor_msgs::LaserScan::ConstPtr& scan);
  void onOdom(const nav_msgs::Odometry::ConstPtr& odom);
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& map);
  void onGoal(const geometry_msgs::PoseStamped::ConstPtr& goal);
  /// Grid: answers the pending goal once the scan, pose and map of its step are in (mutex_ held).
  void serve();
  /// Continuous motion: answers each control period once its scan and pose are in (mutex_ held).
  void drive();
  /// Publishes the answer to the request stamped `stamp` (mutex_ held).
  void respond(const ros::Time& stamp, const sensor_msgs::LaserScan& scan, const nav_msgs::Odometry& pose,
               const geometry_msgs::PoseStamped& goal);

  PlannerFrames frames_;
  ros::Duration control_period_;  // zero on the grid
  Answer answer_;
  std::mutex mutex_;  // held by each callback: a nodelet's may run in two threads (a publisher's and its own)
  std::deque<sensor_msgs::LaserScan::ConstPtr> scans_;
  std::deque<nav_msgs::Odometry::ConstPtr> poses_;
  nav_msgs::OccupancyGrid::ConstPtr map_message_;
  geometry_msgs::PoseStamped::ConstPtr pending_;    // grid: the goal not answered yet
  geometry_msgs::PoseStamped::ConstPtr goal_pose_;  // continuous motion: the newest goal (the episode's)
  ros::Time answered_;                              // the last request or period answered
  ros::Time episode_;                               // the map_load_time of the episode being played
  ros::Publisher command_;
  ros::Publisher status_;
  ppp_msgs::LockstepQueue queue_;  // before the subscriptions: they unsubscribe first
  ros::Subscriber scan_, odom_, map_, goal_;
};

}  // namespace planners
}  // namespace ppp
