#include "planner_bridge_messages.hpp"

#include <cmath>

#include "ppp_msgs/conversions.h"
#include "ppp_msgs/graph_names.h"

namespace ppp {
namespace agents {

std::string bareFrame(const std::string& frame) { return frame.empty() || frame[0] != '/' ? frame : frame.substr(1); }

std::string pathPoints(const nav_msgs::Path& path, const std::string& map_frame, std::vector<MapPoint>* points) {
  points->clear();
  if (bareFrame(path.header.frame_id) != map_frame) {
    return "the path is in frame '" + path.header.frame_id + "'; expected '" + map_frame + "'";
  }
  for (const geometry_msgs::PoseStamped& pose : path.poses) {
    const std::string frame = bareFrame(pose.header.frame_id);
    if (!frame.empty() && frame != map_frame) {
      return "a pose of the path is in frame '" + pose.header.frame_id + "'; expected '" + map_frame +
             "'";
    }
    if (!std::isfinite(pose.pose.position.x) || !std::isfinite(pose.pose.position.y)) {
      return "a pose of the path is not a finite point";
    }
    points->push_back(MapPoint{pose.pose.position.x, pose.pose.position.y});
  }
  return "";
}

std::string commandOf(const geometry_msgs::TwistStamped& command, const std::string& base_frame,
                      const std::string& map_frame, VelocityCommand* velocity) {
  const std::string frame = bareFrame(command.header.frame_id);
  if (!frame.empty() && frame != bareFrame(base_frame) && frame != bareFrame(map_frame)) {
    return "the command is in frame '" + command.header.frame_id + "', not '" + base_frame + "' (or '" + map_frame +
           "', which is aligned with it)";
  }
  const geometry_msgs::Twist& t = command.twist;
  *velocity = VelocityCommand{t.linear.x, t.linear.y, t.linear.z, t.angular.x, t.angular.y, t.angular.z};
  return "";
}

nav_msgs::Odometry odometryOf(const geometry_msgs::TransformStamped& transform) {
  nav_msgs::Odometry odom;
  odom.header = transform.header;
  odom.child_frame_id = transform.child_frame_id;
  odom.pose.pose.position.x = transform.transform.translation.x;
  odom.pose.pose.position.y = transform.transform.translation.y;
  odom.pose.pose.position.z = transform.transform.translation.z;
  odom.pose.pose.orientation = transform.transform.rotation;
  return odom;
}

std::string odomFrameOf(const std::string& base_frame) {
  const std::size_t slash = base_frame.rfind('/');
  return slash == std::string::npos ? ppp_msgs::frames::kOdom : base_frame.substr(0, slash + 1) + ppp_msgs::frames::kOdom;
}

geometry_msgs::PoseStamped goalRequest(const ros::Time& stamp, const std::string& map_frame, MapPoint goal) {
  geometry_msgs::PoseStamped request;
  request.header.stamp = stamp;
  request.header.frame_id = map_frame;
  request.pose.position.x = goal.x;
  request.pose.position.y = goal.y;
  request.pose.orientation.w = 1.0;
  return request;
}

tf2_msgs::TFMessage odometryFrameTransform(const std::string& map_frame, const std::string& base_frame) {
  tf2_msgs::TFMessage transforms;
  transforms.transforms.push_back(ppp_msgs::poseTransform(Pose2D{}, map_frame, odomFrameOf(base_frame)));
  return transforms;
}

tf2_msgs::TFMessage continuousTransforms(const ros::Time& stamp, const Pose2D& pose, const std::string& base_frame) {
  tf2_msgs::TFMessage transforms;
  transforms.transforms.push_back(ppp_msgs::poseTransform(pose, odomFrameOf(base_frame), base_frame));
  transforms.transforms.back().header.stamp = stamp;
  return transforms;
}

nav_msgs::Odometry odometryOf(const geometry_msgs::TransformStamped& transform, const BodyVelocity& velocity) {
  nav_msgs::Odometry odometry = odometryOf(transform);
  odometry.twist.twist.linear.x = velocity.forward;
  odometry.twist.twist.linear.y = velocity.left;
  odometry.twist.twist.angular.z = velocity.turn;
  return odometry;
}

}  // namespace agents
}  // namespace ppp
