#pragma once

#include <string>
#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <geometry_msgs/PoseStamped.h>
#include <tf2_msgs/TFMessage.h>

#include "ppp_agents/planner_episode.hpp"
#include "ppp_agents/velocity_command.hpp"
#include "ppp_core/kinematics.hpp"

namespace ppp {
namespace agents {

/// A frame name without a leading slash (tf2 frames have none).
std::string bareFrame(const std::string& frame);

/// Turns a planner's path into map points, checking that it and each pose are in `map_frame` (a pose may leave
/// its frame empty) and every point is finite. Returns "" or what is wrong.
std::string pathPoints(const nav_msgs::Path& path, const std::string& map_frame, std::vector<MapPoint>* points);

/// Turns a local planner's velocity command into a VelocityCommand, checking that it is in the robot's frame
/// `base_frame` or the map's (aligned with it), or has none. Returns "" or what is wrong.
std::string commandOf(const geometry_msgs::TwistStamped& command, const std::string& base_frame,
                      const std::string& map_frame, VelocityCommand* velocity);

/// The odometry frame of a robot whose frame is `base_frame`: its sibling "odom" ("ompl/robot/base_link" ->
/// "ompl/robot/odom"; "base_link" -> "odom").
std::string odomFrameOf(const std::string& base_frame);

/// A plan request: the goal `goal` (map frame `map_frame`), stamped `stamp`.
geometry_msgs::PoseStamped goalRequest(const ros::Time& stamp, const std::string& map_frame, MapPoint goal);

/// Continuous motion's static tf: `map_frame` -> odom, the identity (odometry is exact; the odometry frame is
/// odomFrameOf(base_frame)).
tf2_msgs::TFMessage odometryFrameTransform(const std::string& map_frame, const std::string& base_frame);

/// Continuous motion's tf at `stamp`: odom -> `base_frame` at `pose`.
tf2_msgs::TFMessage continuousTransforms(const ros::Time& stamp, const Pose2D& pose, const std::string& base_frame);

/// odometryOf(transform) moving at `velocity` (its twist, in the robot's frame).
nav_msgs::Odometry odometryOf(const geometry_msgs::TransformStamped& transform, const BodyVelocity& velocity);

/// The odometry a planner reads the robot's pose from: the pose `transform` gives its child frame in its parent
/// frame (header and child frame as the transform's).
nav_msgs::Odometry odometryOf(const geometry_msgs::TransformStamped& transform);

}  // namespace agents
}  // namespace ppp
