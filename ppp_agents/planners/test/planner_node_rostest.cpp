// PlannerNode plans each episode towards that episode's goal: a map that starts a new episode (a new
// info.map_load_time) before its goal has come is not planned on towards the previous episode's goal, and a planner
// with a memory of its own hears episode_started once per episode, before its first plan there; a new episode's goal
// that comes before its map is planned once the map and the pose have come.
// The test publishes as the bridge does, handing over, so each callback runs in the publishing call: "not planned"
// is a fact, not a wait.
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <boost/make_shared.hpp>

#include <memory>
#include <string>
#include <vector>

#include "planner_node.hpp"
#include "ppp_msgs/graph_names.h"
#include "ppp_msgs/hand_over.h"

namespace ppp {
namespace planners {
namespace {

/// One call of the planner: the cells it planned between, and how many episodes had started by then.
struct Planned {
  Cell robot;
  Cell goal;
  int episodes = 0;
};

/// The bridge's side of a replanning planner node on a 5 x 5 map of 1 m cells, the robot in its bottom-left cell.
class BridgeSide {
 public:
  explicit BridgeSide(const std::string& ns) : nh_(ns) {
    namespace names = ppp_msgs::topics;
    map_ = nh_.advertise<nav_msgs::OccupancyGrid>(names::kPlannerMap, 2);
    odom_ = nh_.advertise<nav_msgs::Odometry>(names::kPlannerOdom, 10);
    goal_ = nh_.advertise<geometry_msgs::PoseStamped>(names::kPlannerGoal, 10);
    PlannerNodeOptions options;
    options.frames.base_frame = "robot/base_link";
    options.replan_on_map = true;
    options.episode_started = [this] { ++episodes_; };
    node_ = std::make_unique<PlannerNode>(
        nh_, options,
        [this](const GridMap&, Cell robot, Cell goal) {
          planned_.push_back({robot, goal, episodes_});
          return std::vector<MapPoint>{};
        },
        /*in_network_thread=*/false);
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(30.0);
    while (ros::ok() && ros::WallTime::now() < deadline && !connected()) {
      ros::WallDuration(0.02).sleep();  // a connection count has no event to wait on
    }
  }

  bool connected() const {
    return map_.getNumSubscribers() > 0 && odom_.getNumSubscribers() > 0 && goal_.getNumSubscribers() > 0;
  }

  /// The robot's map at `stamp` of the episode started at `episode_start`, `obstacles` of its cells occupied.
  void map(double stamp, double episode_start, int obstacles) {
    auto map = boost::make_shared<nav_msgs::OccupancyGrid>();
    map->header.stamp = ros::Time(stamp);
    map->header.frame_id = "map";
    map->info.map_load_time = ros::Time(episode_start);
    map->info.width = map->info.height = 5;
    map->info.resolution = 1.0;
    map->data.assign(25, 0);
    for (int i = 0; i < obstacles; ++i) map->data[12 + i] = 100;
    ppp_msgs::publishHandingOver(map_, map);
  }
  void odom(double stamp) {
    auto odom = boost::make_shared<nav_msgs::Odometry>();
    odom->header.stamp = ros::Time(stamp);
    odom->header.frame_id = "map";
    odom->child_frame_id = "robot/base_link";
    odom->pose.pose.position.x = odom->pose.pose.position.y = 0.5;
    odom->pose.pose.orientation.w = 1;
    ppp_msgs::publishHandingOver(odom_, odom);
  }
  /// A plan request towards the centre of the cell in column `x` of the map's top row.
  void goal(double stamp, int x) {
    auto goal = boost::make_shared<geometry_msgs::PoseStamped>();
    goal->header.stamp = ros::Time(stamp);
    goal->header.frame_id = "map";
    goal->pose.position.x = x + 0.5;
    goal->pose.position.y = 4.5;
    goal->pose.orientation.w = 1;
    ppp_msgs::publishHandingOver(goal_, goal);
  }

  /// Episode 1 starts at t = 1, its goal in column 4: map, pose, then the request, as the bridge publishes them.
  void firstEpisode() {
    map(1.0, 1.0, 0);
    odom(1.0);
    goal(1.0, 4);
  }

  const std::vector<Planned>& planned() const { return planned_; }
  int episodes() const { return episodes_; }

 private:
  ros::NodeHandle nh_;
  ros::Publisher map_, odom_, goal_;
  std::vector<Planned> planned_;
  int episodes_ = 0;
  std::unique_ptr<PlannerNode> node_;
};

TEST(PlannerNodeEpisodes, ANewEpisodesMapWaitsForItsOwnGoal) {
  BridgeSide bridge("episodes");
  ASSERT_TRUE(bridge.connected());
  bridge.firstEpisode();
  ASSERT_EQ(bridge.planned().size(), 1u);
  const Cell first_goal = bridge.planned()[0].goal;
  EXPECT_EQ(first_goal.x, 4);
  EXPECT_EQ(bridge.planned()[0].episodes, 1);  // told before its first plan
  // A step later the robot knows an obstacle more: a new plan, towards the same goal, in the same episode.
  bridge.map(2.0, 1.0, 1);
  bridge.odom(2.0);
  ASSERT_EQ(bridge.planned().size(), 2u);
  EXPECT_EQ(bridge.planned()[1].goal, first_goal);
  EXPECT_EQ(bridge.episodes(), 1);
  // Episode 2 starts at t = 3 with a map that differs: nothing is planned until its own goal, in column 2, comes.
  bridge.map(3.0, 3.0, 2);
  bridge.odom(3.0);
  EXPECT_EQ(bridge.planned().size(), 2u) << "planned towards the previous episode's goal";
  bridge.goal(3.0, 2);
  ASSERT_EQ(bridge.planned().size(), 3u);
  EXPECT_EQ(bridge.planned()[2].goal.x, 2);
  EXPECT_EQ(bridge.planned()[2].episodes, 2);
  EXPECT_EQ(bridge.episodes(), 2);
}

TEST(PlannerNodeEpisodes, ANewEpisodesGoalBeforeItsMapIsPlannedOnceBothHaveCome) {
  BridgeSide bridge("early_goal");
  ASSERT_TRUE(bridge.connected());
  bridge.firstEpisode();
  ASSERT_EQ(bridge.planned().size(), 1u);
  // Episode 2's goal comes first (another connection may be faster): it waits for a map and pose of its stamp.
  bridge.goal(3.0, 2);
  EXPECT_EQ(bridge.planned().size(), 1u);
  bridge.map(3.0, 3.0, 2);
  EXPECT_EQ(bridge.planned().size(), 1u);
  bridge.odom(3.0);
  ASSERT_EQ(bridge.planned().size(), 2u);
  EXPECT_EQ(bridge.planned()[1].goal.x, 2);
  EXPECT_EQ(bridge.planned()[1].episodes, 2);
}

}  // namespace
}  // namespace planners
}  // namespace ppp

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "planner_node_rostest");
  ros::NodeHandle keep_alive;  // the node's connection to the master for the whole test
  return RUN_ALL_TESTS();
}
