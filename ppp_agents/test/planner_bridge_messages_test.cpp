// A planner's nav_msgs/Path as map points, a local planner's velocity command (frames and finite points
// checked), and the robot's pose as the odometry a planner reads.

#include "planner_bridge_messages.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace ppp {
namespace agents {
namespace {

nav_msgs::Path path(const std::string& frame, std::initializer_list<std::pair<double, double>> points) {
  nav_msgs::Path p;
  p.header.frame_id = frame;
  for (const auto& [x, y] : points) {
    geometry_msgs::PoseStamped pose;
    pose.pose.position.x = x;
    pose.pose.position.y = y;
    p.poses.push_back(pose);
  }
  return p;
}

TEST(PlannerBridgeMessagesTest, AMapFramePathBecomesItsPoints) {
  std::vector<MapPoint> points;
  EXPECT_EQ(pathPoints(path("/map", {{0.5, 0.5}, {2.5, 0.5}}), "map", &points), "");
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[1].x, 2.5);
  EXPECT_EQ(bareFrame("/map"), "map");
  EXPECT_EQ(bareFrame("odom"), "odom");
}

TEST(PlannerBridgeMessagesTest, WrongFramesAndPointsAreNamed) {
  std::vector<MapPoint> points;
  EXPECT_EQ(pathPoints(path("odom", {{0.5, 0.5}}), "map", &points), "the path is in frame 'odom'; expected 'map'");
  nav_msgs::Path mixed = path("map", {{0.5, 0.5}});
  mixed.poses[0].header.frame_id = "odom";
  EXPECT_EQ(pathPoints(mixed, "map", &points), "a pose of the path is in frame 'odom'; expected 'map'");
  EXPECT_EQ(pathPoints(path("map", {{std::numeric_limits<double>::quiet_NaN(), 0.5}}), "map", &points),
            "a pose of the path is not a finite point");
}

TEST(PlannerBridgeMessagesTest, ACommandInTheRobotsOrTheMapsFrameIsTaken) {
  geometry_msgs::TwistStamped command;
  command.twist.linear.x = 0.5;
  command.twist.angular.z = 2;
  VelocityCommand velocity;
  for (const char* frame : {"", "mine/robot/base_link", "/mine/robot/base_link", "map"}) {
    command.header.frame_id = frame;
    EXPECT_EQ(commandOf(command, "mine/robot/base_link", "map", &velocity), "") << frame;
    EXPECT_EQ(velocity.linear_x, 0.5);
    EXPECT_EQ(velocity.angular_z, 2);
  }
  command.header.frame_id = "odom";
  EXPECT_EQ(commandOf(command, "mine/robot/base_link", "map", &velocity),
            "the command is in frame 'odom', not 'mine/robot/base_link' (or 'map', which is aligned with it)");
}

// The robot's pose as odometry: the transform's translation and rotation, header and child frame.
TEST(PlannerBridgeMessagesTest, OdometryIsThePoseTheTransformGives) {
  geometry_msgs::TransformStamped transform;
  transform.header.frame_id = "map";
  transform.header.stamp = ros::Time(12, 5);
  transform.child_frame_id = "g/robot/base_link";
  transform.transform.translation.x = 2.5;
  transform.transform.translation.y = 7.5;
  transform.transform.rotation.w = 1.0;
  const nav_msgs::Odometry odom = odometryOf(transform);
  EXPECT_EQ(odom.header.frame_id, "map");
  EXPECT_EQ(odom.header.stamp, ros::Time(12, 5));
  EXPECT_EQ(odom.child_frame_id, "g/robot/base_link");
  EXPECT_EQ(odom.pose.pose.position.x, 2.5);
  EXPECT_EQ(odom.pose.pose.position.y, 7.5);
  EXPECT_EQ(odom.pose.pose.position.z, 0.0);
  EXPECT_EQ(odom.pose.pose.orientation.w, 1.0);
}

}  // namespace
}  // namespace agents
}  // namespace ppp
