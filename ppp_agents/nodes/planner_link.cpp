#include "planner_link.hpp"

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/master.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include <boost/make_shared.hpp>

#include <algorithm>

#include "planner_bridge_messages.hpp"
#include "ppp_core/error.hpp"
#include "ppp_msgs/conversions.h"
#include "ppp_msgs/node_liveness.h"
#include "ppp_msgs/graph_names.h"
#include "ppp_msgs/hand_over.h"

namespace ppp {
namespace agents {

namespace {

constexpr double kProbePeriod = 0.2;  // seconds between asks whether the planner's process is alive

/// The type the master has for `topic` ("" when nobody advertises it).
std::string advertisedType(const std::string& topic) {
  ros::master::V_TopicInfo topics;
  if (!ros::master::getTopics(topics)) return "";
  for (const ros::master::TopicInfo& t : topics) {
    if (t.name == topic) return t.datatype;
  }
  return "";
}

}  // namespace

PlannerLink::PlannerLink(ros::NodeHandle& nh, const BridgeParameters& parameters, bool in_network_thread)
    : parameters_(parameters), nh_(nh, ppp_msgs::topics::kRobotNamespace), queue_(in_network_thread) {
  map_ = nh_.advertise<nav_msgs::OccupancyGrid>(ppp_msgs::topics::kPlannerMap, 1, true);
  odom_ = nh_.advertise<nav_msgs::Odometry>(ppp_msgs::topics::kPlannerOdom, 10);
  scan_ = nh_.advertise<sensor_msgs::LaserScan>(ppp_msgs::topics::kPlannerScan, 10);
  // Latched when it goes out once an episode: a planner that connects later still gets the episode's goal.
  goal_ = nh_.advertise<geometry_msgs::PoseStamped>(ppp_msgs::topics::kPlannerGoal, 10, sendsChangesOnly(parameters));
  // Latched: a planner that subscribes late still learns the time (rospy's first sleep waits for it).
  clock_ = nh_.advertise<rosgraph_msgs::Clock>(ppp_msgs::topics::kPlannerClock, 10, true);
  tf_ = nh.advertise<tf2_msgs::TFMessage>("/tf", 100);
  tf_static_ = nh.advertise<tf2_msgs::TFMessage>("/tf_static", 1, true);
  // Without Nagle's algorithm (it would hold each answer back 40 ms).
  if (commandsVelocity(parameters_)) {
    subscribeVelocityAnswers();
  } else {
    answers_ = ppp_msgs::subscribeLockstep<nav_msgs::Path>(
        nh_, ppp_msgs::topics::kPlannerPath, 10,
        [this](const nav_msgs::Path::ConstPtr& path) { paths_.put(*path); }, queue_.get());
  }
  // The robot's body as costmaps read it, in metres, for planners that plan with a footprint.
  const double radius = parameters_.robot_radius * parameters_.resolution;
  nh_.setParam(ppp_msgs::topics::kPlannerRobotRadius, radius);
  if (parameters_.robot_radius > 0) {
    XmlRpc::XmlRpcValue footprint;
    footprint.setSize(0);
    int vertex = 0;
    for (const auto& [x, y] : footprintPolygon(radius)) {
      footprint[vertex][0] = x;
      footprint[vertex++][1] = y;
    }
    nh_.setParam(ppp_msgs::topics::kPlannerFootprint, footprint);
  }
}

std::string PlannerLink::topics() const {
  return map_.getTopic() + ", " + odom_.getTopic() + ", " + scan_.getTopic() + ", " + goal_.getTopic() + " -> " +
         answers_.getTopic() + "; tf " + parameters_.map_frame + " -> " + parameters_.base_frame;
}

bool PlannerLink::waitForPlanner() {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(parameters_.connect_timeout);
  std::string wrong_type;
  for (int poll = 0; running(); ++poll) {
    if (goal_.getNumSubscribers() > 0 && connected()) return true;
    if (poll % 10 == 0) {
      const std::string type = advertisedType(answers_.getTopic());
      if (!type.empty() && type != answerType()) {
        wrong_type = answers_.getTopic() + " is published as " + type + "; expected " + answerType();
        break;
      }
    }
    if (ros::WallTime::now() >= deadline) break;
    ros::WallDuration(0.05).sleep();  // polling connection counts: there is no event to wait on
  }
  if (!running()) return false;
  std::string missing = wrong_type;
  const auto add = [&missing](const std::string& text) { missing += (missing.empty() ? "" : "; ") + text; };
  if (wrong_type.empty() && !connected()) {
    add("nothing publishes " + answers_.getTopic() + " (" + answerType() + ")");
  }
  if (goal_.getNumSubscribers() == 0) {
    add("nothing subscribes to " + goal_.getTopic() +
        " (geometry_msgs/PoseStamped; a subscriber of another type cannot connect)");
  }
  throw InvalidArgument("planner", missing + ". Start the planner in namespace " + nh_.getNamespace() +
                                       " or remap its topics to these names (docs/reference/planner-interface.md)");
}

const char* PlannerLink::answerType() const {
  return commandsVelocity(parameters_) ? "geometry_msgs/TwistStamped" : "nav_msgs/Path";
}

void PlannerLink::newEpisode() {
  answered_ = false;
  // An answer sent for an earlier episode is not this one's.
  paths_.skipReceived();
  commands_.skipReceived();
}

std::optional<nav_msgs::Path> PlannerLink::takeUnasked() {
  std::lock_guard<std::mutex> lock(paths_.mutex);
  std::optional<nav_msgs::Path> unasked;
  if (paths_.received > paths_.used) unasked = paths_.latest;
  paths_.used = paths_.received;
  return unasked;
}

bool PlannerLink::gone() {
  if (!answered_) return false;
  if (!connected()) return true;
  // A killed process leaves its link retrying and its registration in place: ask it, a few times a second.
  const ros::WallTime now = ros::WallTime::now();
  if (now < next_probe_) return false;
  next_probe_ = now + ros::WallDuration(kProbePeriod);
  return !ppp_msgs::publisherAlive(answers_.getTopic());
}

bool PlannerLink::alive() const { return connected() && ppp_msgs::publisherAlive(answers_.getTopic()); }

template <class Message>
std::optional<Message> PlannerLink::waitFor(AnswerInbox<Message>* inbox, const ros::Time& request,
                                            const std::function<bool(const Message&)>& fits,
                                            const std::function<void()>& resend) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(parameters_.plan_timeout);
  ros::WallTime resend_at = ros::WallTime::now() + ros::WallDuration(1.0);
  std::optional<Message> unusable;  // the last answer that does not fit the request
  lost_ = false;
  std::unique_lock<std::mutex> lock(inbox->mutex);
  while (running()) {
    if (inbox->received > inbox->used) {
      inbox->used = inbox->received;
      // An answer stamped before the request answers an earlier one (stamp 0 means "now"). A path that does not
      // fit (not from the robot's cell, not to the goal, through a known wall) may still be a late answer to an
      // earlier request carrying a newer map's stamp: wait for another, and judge it if none comes.
      const Message& answer = *inbox->latest;
      const bool unstamped = answer.header.stamp.isZero();
      if (unstamped && parameters_.lockstep) {
        ROS_WARN_ONCE("an unstamped answer does not answer a lockstep request: stamp it with the goal's stamp "
                      "(docs/reference/planner-interface.md)");
      } else if (unstamped || answer.header.stamp >= request) {
        if (fits(answer)) {
          answered_ = true;
          return answer;
        }
        unusable = answer;
      }
    }
    // A planner that answered in this episode and is gone now died mid-episode: no point waiting.
    if (gone()) {
      lost_ = true;  // a planner restarted since is another process: this request's died with the first
      break;
    }
    const ros::WallTime now = ros::WallTime::now();
    if (now >= deadline) break;
    if (now >= resend_at) {
      // A planner that (re)started since the request missed it, or one waiting for its timer: ask again.
      lock.unlock();
      resend();
      lock.lock();
      resend_at = now + ros::WallDuration(1.0);
      continue;
    }
    // Wake at least every 50 ms to see whether the planner is still connected (no event says it left).
    const ros::WallTime until = std::min({deadline, resend_at, now + ros::WallDuration(0.05)});
    inbox->arrived.wait_for(lock, std::chrono::nanoseconds((until - now).toNSec()));
  }
  if (unusable) answered_ = true;
  return unusable;
}

std::optional<nav_msgs::Path> PlannerLink::waitForPath(const ros::Time& request,
                                                       const std::function<bool(const nav_msgs::Path&)>& fits,
                                                       const std::function<void()>& resend) {
  return waitFor(&paths_, request, fits, resend);
}

std::optional<VelocityAnswer> PlannerLink::waitForCommand(const ros::Time& request,
                                                         const std::function<void()>& resend) {
  return waitFor<VelocityAnswer>(
      &commands_, request, [](const VelocityAnswer&) { return true; }, resend);
}

void PlannerLink::publishState(const ros::Time& stamp, const ros::Time& episode_stamp, const PlannerEpisode& episode,
                               Cell robot, const std::int8_t* window, int range) {
  const MapFrame& frame = episode.frame();
  // New messages, published by pointer and handing over: a planner nodelet of the same manager gets these objects.
  auto map = boost::make_shared<nav_msgs::OccupancyGrid>(
      ppp_msgs::toFinerOccupancyGrid(episode.known().cells, frame.width, frame.height, parameters_.resolution,
                                     parameters_.cells_per_ppp_cell, parameters_.map_frame));
  map->header.stamp = stamp;
  map->info.map_load_time = episode_stamp;
  ppp_msgs::publishHandingOver(map_, map);
  publishPose(stamp, episode, robot, window, range);
}

void PlannerLink::publishPose(const ros::Time& stamp, const PlannerEpisode& episode, Cell robot,
                              const std::int8_t* window, int range) {
  const MapFrame& frame = episode.frame();
  auto transforms = boost::make_shared<tf2_msgs::TFMessage>();
  transforms->transforms.push_back(
      ppp_msgs::cellTransform(frame, robot, parameters_.map_frame, parameters_.base_frame));
  const geometry_msgs::TransformStamped& transform = transforms->transforms.back();
  transforms->transforms.back().header.stamp = stamp;
  ppp_msgs::publishHandingOver(tf_, transforms);

  ppp_msgs::publishHandingOver(odom_, boost::make_shared<nav_msgs::Odometry>(odometryOf(transform)));

  if (scan_.getNumSubscribers() == 0) return;  // rays cost a cast each: only for a planner that reads them
  auto laser = boost::make_shared<sensor_msgs::LaserScan>(
      ppp_msgs::toLaserScan(window, range, parameters_.resolution, parameters_.base_frame));
  laser->header.stamp = stamp;
  ppp_msgs::publishHandingOver(scan_, laser);
}

void PlannerLink::publishGoal(const ros::Time& stamp, const PlannerEpisode& episode) {
  const MapPoint goal{episode.frame().centreX(episode.goal()), episode.frame().centreY(episode.goal())};
  ppp_msgs::publishHandingOver(
      goal_, boost::make_shared<geometry_msgs::PoseStamped>(goalRequest(stamp, parameters_.map_frame, goal)));
}

}  // namespace agents
}  // namespace ppp
