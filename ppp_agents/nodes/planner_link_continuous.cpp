// PlannerLink's side of continuous motion: the map at an episode's start, each control period's messages and the
// planner's clock (planner_link.hpp).
#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include <boost/make_shared.hpp>

#include "planner_bridge_messages.hpp"
#include "planner_link.hpp"
#include "ppp_msgs/conversions.h"
#include "ppp_msgs/hand_over.h"

namespace ppp {
namespace agents {

void PlannerLink::publishContinuousMap(const ros::Time& stamp, const ros::Time& episode_stamp, const MapFrame& frame,
                                       const std::vector<std::int8_t>& cells) {
  auto map = boost::make_shared<nav_msgs::OccupancyGrid>(ppp_msgs::toFinerOccupancyGrid(
      cells, frame.width, frame.height, frame.resolution, parameters_.cells_per_ppp_cell, parameters_.map_frame));
  map->header.stamp = stamp;
  map->info.map_load_time = episode_stamp;
  ppp_msgs::publishHandingOver(map_, map);
}

void PlannerLink::publishContinuous(const ros::Time& stamp, const Pose2D& pose, const BodyVelocity& velocity,
                                    const std::vector<float>& ranges, const LaserBeams& beams,
                                    const std::optional<MapPoint>& request) {
  auto transforms = boost::make_shared<tf2_msgs::TFMessage>(
      continuousTransforms(stamp, pose, parameters_.base_frame));
  auto odometry = boost::make_shared<nav_msgs::Odometry>(odometryOf(transforms->transforms.back(), velocity));
  ppp_msgs::publishHandingOver(tf_, transforms);
  ppp_msgs::publishHandingOver(odom_, odometry);
  auto laser = boost::make_shared<sensor_msgs::LaserScan>(ppp_msgs::toLaserScan(ranges, beams, parameters_.base_frame));
  laser->header.stamp = stamp;
  ppp_msgs::publishHandingOver(scan_, laser);
  if (request) {
    ppp_msgs::publishHandingOver(
        goal_, boost::make_shared<geometry_msgs::PoseStamped>(goalRequest(stamp, parameters_.map_frame, *request)));
  }
  publishClock(stamp);
}

void PlannerLink::publishOdometryFrame() {
  tf_static_.publish(odometryFrameTransform(parameters_.map_frame, parameters_.base_frame));
}

void PlannerLink::publishClock(const ros::Time& stamp) {
  auto clock = boost::make_shared<rosgraph_msgs::Clock>();
  clock->clock = stamp;
  ppp_msgs::publishHandingOver(clock_, clock);
}

}  // namespace agents
}  // namespace ppp
