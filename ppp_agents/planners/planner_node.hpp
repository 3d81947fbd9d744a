#pragma once

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf2/buffer_core.h>
#include <tf2_msgs/TFMessage.h>

#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "grid_map.hpp"
#include "ppp_msgs/lockstep_queue.h"
#include "planner_node_parameters.hpp"

namespace ppp {
namespace planners {

/// A planner's answer: map-frame waypoints from the robot's cell to the goal's, empty when it finds no path.
using PlanFunction = std::function<std::vector<MapPoint>(const GridMap& map, Cell robot, Cell goal)>;

/// The planner's view of a map message (`inflation` in map cells, as GridMap takes it).
/// @throws InvalidArgument when it does not follow the interface (origin (0, 0)) or GridMap refuses it.
GridMap gridMapOf(const nav_msgs::OccupancyGrid& map, bool unknown_is_free, double inflation);

/// How a PlannerNode serves its planner.
struct PlannerNodeOptions {
  PlannerFrames frames;         ///< The map and robot frames.
  bool unknown_is_free = true;  ///< Unknown map cells (-1) are passable.
  bool replan_on_map = false;   ///< Plan again on every new map while there is a goal the robot is not at.
  PlannerBody body;             ///< The robot's body as the planner believes it (its inflation).
  /// Called before the first plan of each episode (a map whose info.map_load_time differs from the last plan's): a
  /// planner with a memory of its own starts afresh.
  std::function<void()> episode_started;
};

/// The ROS side of the example planners (docs/reference/planner-interface.md): keeps the newest `map`, answers every
/// `move_base_simple/goal` with a nav_msgs/Path on `plan` once it holds a map at least as new as the goal and
/// the robot's pose at the goal's stamp (`odom`, child base_frame, in map_frame or in a frame /tf_static places in
/// it, as continuous motion's odom; a newer goal replaces one still waiting for them), and, with replan_on_map, plans again on every new map. A plan is stamped with the stamp of the
/// pose it starts from (the goal's; a re-plan's map's); no path gives an empty Path. A request the last plan still
/// answers (the same state, or the robot further along it on an unchanged map: a lockstep bridge asks every step) is
/// answered with that plan again, not a new one. It plans in the callback that completes a request, so no thread
/// waits for another: in roscpp's network thread (a process of its own), or, as a nodelet, in the thread of a bridge
/// of the same manager that published the input (ppp_msgs/lockstep_queue.h).
class PlannerNode {
 public:
  /// Subscribes and advertises in the node's namespace; plans with `plan`. `in_network_thread`: a process of its own.
  PlannerNode(ros::NodeHandle& nh, PlannerNodeOptions options, PlanFunction plan, bool in_network_thread);

  /// The resolved topic names, for the log.
  std::string topics() const;

 private:
  /// One planning job: the goal, the newest map, the stamp of the pose, and the pose.
  struct Request {
    geometry_msgs::PoseStamped::ConstPtr goal;
    nav_msgs::OccupancyGrid::ConstPtr map;
    ros::Time pose_stamp;
    nav_msgs::Odometry::ConstPtr pose;
    bool replan = false;
  };

  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& map);
  void onOdom(const nav_msgs::Odometry::ConstPtr& odom);
  void onGoal(const geometry_msgs::PoseStamped::ConstPtr& goal);
  void onStaticFrames(const tf2_msgs::TFMessage::ConstPtr& transforms);
  /// The robot's position in the map frame from `pose`, into `position`; "" or why it cannot be had.
  std::string positionOf(const nav_msgs::Odometry& pose, MapPoint* position) const;
  /// The newest odometry stamped no later than `stamp`, or null.
  nav_msgs::Odometry::ConstPtr poseAt(const ros::Time& stamp) const;
  /// True when odometry as new as `stamp` has come.
  bool hasPoseAt(const ros::Time& stamp) const { return !poses_.empty() && poses_.back()->header.stamp >= stamp; }
  bool replanDue() const;
  /// Serves the pending goal once its map and pose are in, else a re-plan that is due once its pose is in.
  void serveReady();
  void serve(const Request& request);
  bool keepsLastPlan(const Request& request, const GridMap& map, Cell robot, Cell target) const;
  void publish(const std::vector<MapPoint>& waypoints, const ros::Time& stamp);

  PlannerNodeOptions options_;
  PlanFunction plan_;
  bool plan_time_logged_ = false;
  // The last plan: what a request for the same state, or a step along it on the same map, is answered with again.
  struct LastPlan {
    std::vector<MapPoint> waypoints;
    Cell from{-1, -1};
    Cell target{-1, -1};
    ros::Time stamp;
    nav_msgs::OccupancyGrid::ConstPtr map;
  } last_plan_;

  std::mutex mutex_;  // held by each callback: a nodelet's may run in two threads (a publisher's and its own)
  nav_msgs::OccupancyGrid::ConstPtr map_;
  geometry_msgs::PoseStamped::ConstPtr goal_;
  bool goal_pending_ = false;                      // goal_ has not been planned for yet
  bool goal_reached_ = false;                      // a re-plan found the robot on goal_
  nav_msgs::OccupancyGrid::ConstPtr planned_map_;  // the newest map when the last request was served
  ros::Time planned_episode_;                      // the info.map_load_time of the map last planned on
  std::deque<nav_msgs::Odometry::ConstPtr> poses_;  // the newest odometry messages, oldest first
  tf2::BufferCore static_frames_;                   // what /tf_static says (thread-safe)

  ros::Publisher plan_publisher_;
  ppp_msgs::LockstepQueue queue_;  // before the subscriptions: they unsubscribe first
  ros::Subscriber map_subscriber_;
  ros::Subscriber odom_subscriber_;
  ros::Subscriber goal_subscriber_;
  ros::Subscriber static_frames_subscriber_;
};

}  // namespace planners
}  // namespace ppp
