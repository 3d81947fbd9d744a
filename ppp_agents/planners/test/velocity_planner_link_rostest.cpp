// VelocityPlannerLink answers each request once. In continuous motion it answers a control period once its scan and
// odometry are in; a period that does not come one control period after the last one answered begins an episode,
// and is answered only with the goal and map stamped with it, in whatever order its topics arrive: a planner in a
// process of its own reads each topic on a connection of its own, so the scan of an episode's first period can come
// before the map that starts the episode (the link would then play the period in the previous episode, with that
// episode's memory) and before the period's goal. The bridge sends the map and goal with every period
// (period_messages every) or with an episode's first only (changes): the same rule answers both.
// The test publishes as the bridge does, handing over, so each callback runs in the publishing call: the order of
// arrival is the order of the calls below, and "not answered yet" is a fact, not a wait.
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <boost/make_shared.hpp>
#include <geometry_msgs/TwistStamped.h>

#include <memory>
#include <string>
#include <vector>

#include "ppp_msgs/graph_names.h"
#include "ppp_msgs/hand_over.h"
#include "ppp_msgs/lockstep_queue.h"
#include "velocity_planner_link.hpp"

namespace ppp {
namespace planners {
namespace {

/// The control period of the continuous tests, seconds.
constexpr double kControlPeriod = 0.1;

/// What the planner was asked, and the command the link published for it.
struct Answered {
  ros::Time command_stamp;
  bool new_episode = false;
  double goal_x = 0;
};

/// The bridge's side of one planner: it publishes the period's messages, one topic at a time, and collects the
/// link's commands.
class BridgeSide {
 public:
  /// `continuous`: the link plays control periods, else grid requests; `ns`: a namespace of the test's own.
  BridgeSide(bool continuous, const std::string& ns)
      : odom_frame_(continuous ? "robot/odom" : "map"), nh_(ns), queue_(false) {
    namespace names = ppp_msgs::topics;
    map_ = nh_.advertise<nav_msgs::OccupancyGrid>(names::kPlannerMap, 2);
    odom_ = nh_.advertise<nav_msgs::Odometry>(names::kPlannerOdom, 10);
    scan_ = nh_.advertise<sensor_msgs::LaserScan>(names::kPlannerScan, 10);
    goal_ = nh_.advertise<geometry_msgs::PoseStamped>(names::kPlannerGoal, 10);
    PlannerFrames frames;
    frames.base_frame = "robot/base_link";
    link_ = std::make_unique<VelocityPlannerLink>(
        nh_, frames, continuous ? kControlPeriod : 0.0, /*in_network_thread=*/false,
        [this](const VelocityRequest& request) {
          asked_.push_back({ros::Time(), request.new_episode, request.goal.pose.position.x});
          return geometry_msgs::Twist();
        });
    commands_ = ppp_msgs::subscribeLockstep<geometry_msgs::TwistStamped>(
        nh_, names::kPlannerCommand, 10,
        [this](const geometry_msgs::TwistStamped::ConstPtr& command) {
          if (!asked_.empty()) asked_.back().command_stamp = command->header.stamp;
        },
        queue_.get());
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(30.0);
    while (ros::ok() && ros::WallTime::now() < deadline && !connected()) {
      ros::WallDuration(0.02).sleep();  // a connection count has no event to wait on
    }
  }

  bool connected() const {
    return map_.getNumSubscribers() > 0 && odom_.getNumSubscribers() > 0 && scan_.getNumSubscribers() > 0 &&
           goal_.getNumSubscribers() > 0 && commands_.getNumPublishers() > 0;
  }

  void map(double stamp, double episode_start) {
    auto map = boost::make_shared<nav_msgs::OccupancyGrid>();
    map->header.stamp = ros::Time(stamp);
    map->header.frame_id = "map";
    map->info.map_load_time = ros::Time(episode_start);
    map->info.width = map->info.height = 2;
    map->info.resolution = 1.0;
    map->data.assign(4, -1);
    ppp_msgs::publishHandingOver(map_, map);
  }
  void goal(double stamp, double x) {
    auto goal = boost::make_shared<geometry_msgs::PoseStamped>();
    goal->header.stamp = ros::Time(stamp);
    goal->header.frame_id = "map";
    goal->pose.position.x = x;
    goal->pose.position.y = 1.5;
    goal->pose.orientation.w = 1;
    ppp_msgs::publishHandingOver(goal_, goal);
  }
  void odom(double stamp) {
    auto odom = boost::make_shared<nav_msgs::Odometry>();
    odom->header.stamp = ros::Time(stamp);
    odom->header.frame_id = odom_frame_;  // continuous motion: odometry's own frame; the grid: the map's
    odom->child_frame_id = "robot/base_link";
    odom->pose.pose.position.x = odom->pose.pose.position.y = 0.5;
    odom->pose.pose.orientation.w = 1;
    ppp_msgs::publishHandingOver(odom_, odom);
  }
  void scan(double stamp) {
    auto scan = boost::make_shared<sensor_msgs::LaserScan>();
    scan->header.stamp = ros::Time(stamp);
    scan->header.frame_id = "robot/base_link";
    scan->angle_increment = 0.1;
    scan->range_max = 10;
    scan->ranges.assign(4, 1.0f);
    ppp_msgs::publishHandingOver(scan_, scan);
  }

  /// The requests the planner was asked so far, each with the stamp of the command the link sent for it.
  const std::vector<Answered>& asked() const { return asked_; }

 private:
  std::string odom_frame_;
  ros::NodeHandle nh_;
  ppp_msgs::LockstepQueue queue_;
  ros::Publisher map_, odom_, scan_, goal_;
  std::vector<Answered> asked_;
  std::unique_ptr<VelocityPlannerLink> link_;
  ros::Subscriber commands_;
};

TEST(VelocityPlannerLinkOrder, EachPeriodIsAnsweredInItsOwnEpisodeWhateverTheOrder) {
  BridgeSide bridge(/*continuous=*/true, "periods");
  ASSERT_TRUE(bridge.connected()) << "the link did not connect within 30 s";

  // Episode A's first period (starting at t = 2 s), in the order the bridge publishes it: answered once, a new
  // episode towards goal A (x = 7.5), when its goal is in.
  bridge.map(2.0, 2.0);
  bridge.odom(2.0);
  bridge.scan(2.0);
  EXPECT_TRUE(bridge.asked().empty()) << "an episode's first period answered before its goal came";
  bridge.goal(2.0, 7.5);
  ASSERT_EQ(bridge.asked().size(), 1u);
  EXPECT_EQ(bridge.asked()[0].command_stamp, ros::Time(2.0));
  EXPECT_TRUE(bridge.asked()[0].new_episode);
  EXPECT_DOUBLE_EQ(bridge.asked()[0].goal_x, 7.5);

  // Its second period, one control period later, with no map or goal of its own (period_messages changes):
  // answered once its scan and odometry are in, in episode A.
  bridge.scan(2.1);
  EXPECT_EQ(bridge.asked().size(), 1u) << "period 2.1 answered before its odometry came";
  bridge.odom(2.1);
  ASSERT_EQ(bridge.asked().size(), 2u);
  EXPECT_EQ(bridge.asked()[1].command_stamp, ros::Time(2.1));
  EXPECT_FALSE(bridge.asked()[1].new_episode);
  EXPECT_DOUBLE_EQ(bridge.asked()[1].goal_x, 7.5);

  // The third with its map and goal too (period_messages every), these last: answered once, when its scan and
  // odometry are in.
  bridge.odom(2.2);
  bridge.scan(2.2);
  ASSERT_EQ(bridge.asked().size(), 3u);
  EXPECT_EQ(bridge.asked()[2].command_stamp, ros::Time(2.2));
  EXPECT_FALSE(bridge.asked()[2].new_episode);
  bridge.goal(2.2, 7.5);
  bridge.map(2.2, 2.0);
  EXPECT_EQ(bridge.asked().size(), 3u) << "period 2.2 answered twice";

  // Episode B (a second after A's end) whose first scan, odometry and goal come before its map: played in B, not in
  // A with A's memory.
  bridge.scan(3.2);
  bridge.odom(3.2);
  bridge.goal(3.2, 4.5);
  EXPECT_EQ(bridge.asked().size(), 3u) << "episode B's first period played with episode A's map";
  bridge.map(3.2, 3.2);
  ASSERT_EQ(bridge.asked().size(), 4u);
  EXPECT_EQ(bridge.asked()[3].command_stamp, ros::Time(3.2));
  EXPECT_TRUE(bridge.asked()[3].new_episode);
  EXPECT_DOUBLE_EQ(bridge.asked()[3].goal_x, 4.5);

  // Episode C, its goal last: played towards C's goal, not B's.
  bridge.map(4.3, 4.3);
  bridge.scan(4.3);
  bridge.odom(4.3);
  EXPECT_EQ(bridge.asked().size(), 4u) << "episode C's first period played towards episode B's goal";
  bridge.goal(4.3, 9.5);
  ASSERT_EQ(bridge.asked().size(), 5u);
  EXPECT_TRUE(bridge.asked()[4].new_episode);
  EXPECT_DOUBLE_EQ(bridge.asked()[4].goal_x, 9.5);

  // A period two control periods on is not one that continues C: it waits for a map and goal of its own.
  bridge.scan(4.5);
  bridge.odom(4.5);
  EXPECT_EQ(bridge.asked().size(), 5u) << "a period two control periods on taken as continuing the episode";

  // A period already answered is not answered again when its messages come twice.
  bridge.scan(4.3);
  bridge.odom(4.3);
  bridge.goal(4.3, 9.5);
  bridge.map(4.3, 4.3);
  EXPECT_EQ(bridge.asked().size(), 5u);
}

TEST(VelocityPlannerLinkOrder, AGridRequestAskedAgainAsItWasIsAnsweredOnce) {
  // The bridge sends a request left unanswered for a wall second again with its own stamp (for a planner that
  // restarted): a planner with a memory of its own must not take it for a second step.
  BridgeSide bridge(/*continuous=*/false, "requests");
  ASSERT_TRUE(bridge.connected()) << "the link did not connect within 30 s";
  bridge.map(5.0, 5.0);
  bridge.odom(5.0);
  bridge.scan(5.0);
  bridge.goal(5.0, 7.5);
  ASSERT_EQ(bridge.asked().size(), 1u);
  EXPECT_EQ(bridge.asked()[0].command_stamp, ros::Time(5.0));
  bridge.map(5.0, 5.0);
  bridge.odom(5.0);
  bridge.scan(5.0);
  bridge.goal(5.0, 7.5);
  EXPECT_EQ(bridge.asked().size(), 1u) << "a request asked again was answered twice";
  bridge.map(6.0, 5.0);
  bridge.odom(6.0);
  bridge.scan(6.0);
  bridge.goal(6.0, 7.5);
  ASSERT_EQ(bridge.asked().size(), 2u);
  EXPECT_EQ(bridge.asked()[1].command_stamp, ros::Time(6.0));
}

}  // namespace
}  // namespace planners
}  // namespace ppp

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "velocity_planner_link_rostest");
  ros::NodeHandle keep_alive;  // the node's connection to the master for the whole test
  return RUN_ALL_TESTS();
}
