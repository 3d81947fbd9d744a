// A planner's nav_msgs/Path as map points: frames and finite points checked.

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

}  // namespace
}  // namespace agents
}  // namespace ppp
